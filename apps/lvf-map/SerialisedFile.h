#pragma once
// One MRPT object read from a file (gzip-compressed or not, as MRPT writes
// .gridmap.gz and .simplemap.gz), or one InputError naming the file: MRPT's
// own exceptions on a corrupt file would reach the user as internal errors.

#include <lvfusion/common/InputError.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <string>

namespace lvf::apps
{
template <typename T>
void readSerialisedFile(const std::string& path, T& object, const std::string& what)
{
	lvf::common::requireRegularInputFile(path, what);
	try
	{
		mrpt::io::CFileGZInputStream in(path);
		mrpt::serialization::archiveFrom(in) >> object;
	}
	catch (const std::exception&)
	{
		throw lvf::common::InputError(path, "", "not a readable MRPT " + std::string(object.GetRuntimeClass()->className));
	}
}

}  // namespace lvf::apps
