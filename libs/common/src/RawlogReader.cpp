#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogReader.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

namespace lvf::common
{
std::vector<mrpt::serialization::CSerializable::Ptr> readRawlogEntries(const std::string& path)
{
	if (!mrpt::system::fileExists(path)) throw InputError(path, "", "input rawlog not found");
	std::vector<mrpt::serialization::CSerializable::Ptr> entries;
	mrpt::io::CFileGZInputStream file(path);
	auto archive = mrpt::serialization::archiveFrom(file);
	for (;;)
	{
		try
		{
			entries.push_back(archive.ReadObject());
		}
		catch (const mrpt::serialization::CExceptionEOF&)
		{
			break;
		}
		catch (const std::exception&)
		{
			throw InputError(
				path, "record " + std::to_string(entries.size()),
				"not an MRPT object: corrupt, truncated or not a rawlog");
		}
	}
	if (entries.empty()) throw InputError(path, "", "empty rawlog");
	return entries;
}

}  // namespace lvf::common
