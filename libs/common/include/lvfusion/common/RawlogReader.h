#pragma once
// Reading a whole rawlog (either MRPT layout) object by object. MRPT's CRawlog
// loader prints its own multi-line errors and keeps going; here a corrupt or
// truncated file is one InputError naming the record.

#include <mrpt/serialization/CSerializable.h>

#include <string>
#include <vector>

namespace lvf::common
{
/** Every object of the file, in order (observations, or actions and sensory
 * frames). Throws InputError if the file is missing, empty or not a rawlog. */
std::vector<mrpt::serialization::CSerializable::Ptr> readRawlogEntries(const std::string& path);

}  // namespace lvf::common
