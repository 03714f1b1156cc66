#include "GzipInputFile.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogReader.h>
#include <lvfusion/common/Suffixes.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <filesystem>

namespace lvf::common
{
RawlogReader::RawlogReader(const std::string& path) : m_path(path)
{
	requireRegularInputFile(path, "input rawlog");
	m_file = std::make_unique<GzipInputFile>(path);
	m_archive = std::make_unique<mrpt::serialization::CArchiveStreamBase<GzipInputFile>>(*m_file);
}

RawlogReader::~RawlogReader() = default;

mrpt::serialization::CSerializable::Ptr RawlogReader::next()
{
	try
	{
		auto object = m_archive->ReadObject();
		m_count++;
		return object;
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
		if (m_count == 0) throw InputError(m_path, "", "empty rawlog");
		return nullptr;
	}
	catch (const std::exception&)
	{
		throw InputError(
			m_path, "record " + std::to_string(m_count), "not an MRPT object: corrupt, truncated or not a rawlog");
	}
}

std::string rawlogName(const std::string& path)
{
	std::string name = std::filesystem::path(path).filename().string();
	const bool gz = stripSuffix(name, ".gz");
	if (!stripSuffix(name, ".rawlog") && !gz) return std::filesystem::path(path).stem().string();  // another extension
	return name;
}

}  // namespace lvf::common
