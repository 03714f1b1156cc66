#include "GzipMemberFile.h"

#include <libdeflate.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/archiveFrom_std_vector.h>

#include <stdexcept>

namespace lvf::common
{
std::vector<uint8_t> archived(const mrpt::serialization::CSerializable& object)
{
	std::vector<uint8_t> bytes;
	auto archive = mrpt::serialization::archiveFrom(bytes);
	archive << object;
	return bytes;
}

void GzipMemberFile::FreeCompressor::operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }

GzipMemberFile::GzipMemberFile(const std::string& path, int level)
	: m_file(path, std::ios::binary), m_compressor(libdeflate_alloc_compressor(level))
{
	if (!m_compressor) throw std::invalid_argument("GzipMemberFile: compression level " + std::to_string(level));
}

GzipMemberFile::~GzipMemberFile() = default;  // ~OutputFile closes silently

void GzipMemberFile::writeMember(const std::vector<uint8_t>& bytes)
{
	m_compressed.resize(libdeflate_gzip_compress_bound(m_compressor.get(), bytes.size()));
	const size_t size =
		libdeflate_gzip_compress(m_compressor.get(), bytes.data(), bytes.size(), m_compressed.data(), m_compressed.size());
	// (The bound holds by libdeflate's contract; 0 would mean it did not.)
	if (size == 0) throw std::logic_error("libdeflate: a gzip member larger than its bound");
	m_file.write(reinterpret_cast<const char*>(m_compressed.data()), static_cast<std::streamsize>(size));
	requireWritten(!m_file.fail(), m_file.path());
}

}  // namespace lvf::common
