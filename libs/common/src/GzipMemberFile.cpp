#include "GzipMemberFile.h"

#include <isa-l/igzip_lib.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/archiveFrom_std_vector.h>

#include <limits>
#include <stdexcept>

namespace lvf::common
{
namespace
{
/** The working memory igzip asks for at `level` (its default sizes). */
size_t levelBufferSize(int level)
{
	switch (level)
	{
		case 0: return 0;
		case 1: return ISAL_DEF_LVL1_DEFAULT;
		case 2: return ISAL_DEF_LVL2_DEFAULT;
		case 3: return ISAL_DEF_LVL3_DEFAULT;
		default: throw std::invalid_argument("GzipMemberFile: compression level " + std::to_string(level));
	}
}
}  // namespace

std::vector<uint8_t> archived(const mrpt::serialization::CSerializable& object)
{
	std::vector<uint8_t> bytes;
	auto archive = mrpt::serialization::archiveFrom(bytes);
	archive << object;
	return bytes;
}

GzipMemberFile::GzipMemberFile(const std::string& path, int level)
	: m_file(path, std::ios::binary), m_level(level), m_levelBuffer(levelBufferSize(level))
{
}

void GzipMemberFile::writeMember(const std::vector<uint8_t>& bytes)
{
	// One-shot compression takes 32-bit sizes; a member is a megabyte or so.
	if (bytes.size() > std::numeric_limits<uint32_t>::max() / 2)
		throw std::length_error("GzipMemberFile: a member of " + std::to_string(bytes.size()) + " bytes");
	// At worst stored blocks: the input, 5 bytes a 64 kB block, the headers.
	m_compressed.resize(bytes.size() + bytes.size() / 8192 + 1024);
	isal_zstream stream;
	isal_deflate_stateless_init(&stream);
	stream.next_in = const_cast<uint8_t*>(bytes.data());  // (igzip does not write to it)
	stream.avail_in = static_cast<uint32_t>(bytes.size());
	stream.next_out = m_compressed.data();
	stream.avail_out = static_cast<uint32_t>(m_compressed.size());
	stream.level = static_cast<uint32_t>(m_level);
	stream.level_buf = m_levelBuffer.empty() ? nullptr : m_levelBuffer.data();
	stream.level_buf_size = static_cast<uint32_t>(m_levelBuffer.size());
	stream.gzip_flag = IGZIP_GZIP;
	stream.end_of_stream = 1;
	// (The bound holds by the format; anything else is a bug here.)
	if (isal_deflate_stateless(&stream) != COMP_OK) throw std::logic_error("igzip: a gzip member not compressed");
	m_file.write(reinterpret_cast<const char*>(m_compressed.data()), static_cast<std::streamsize>(stream.total_out));
	requireWritten(!m_file.fail(), m_file.path());
}

}  // namespace lvf::common
