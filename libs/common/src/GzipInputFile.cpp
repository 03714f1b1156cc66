#include "GzipInputFile.h"

#include <lvfusion/common/InputError.h>

#include <isa-l/igzip_lib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace lvf::common
{
namespace
{
/** Bytes of the file read at a time. */
constexpr size_t kInputBytes = size_t{1} << 18;

/** Whether `bytes` begin as a gzip member does (RFC 1952's magic). */
bool startsGzipMember(const uint8_t* bytes, size_t size) { return size >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b; }
}  // namespace

GzipInputFile::GzipInputFile(const std::string& path) : m_path(path), m_file(path, std::ios::binary)
{
	if (!m_file) throw InputError(path, "", "cannot be read");
	uint8_t magic[2] = {0, 0};
	m_file.read(reinterpret_cast<char*>(magic), 2);
	m_gzip = startsGzipMember(magic, static_cast<size_t>(m_file.gcount()));
	m_file.clear();
	m_file.seekg(0);
	if (!m_gzip) return;
	m_state = std::make_unique<inflate_state>();
	isal_inflate_init(m_state.get());
	m_state->crc_flag = ISAL_GZIP;	// the header parsed, the trailer's CRC checked
	m_in.resize(kInputBytes);
	m_state->next_in = m_in.data();
	m_state->avail_in = 0;
}

GzipInputFile::~GzipInputFile() = default;

size_t GzipInputFile::Read(void* buffer, size_t count)
{
	size_t done;
	if (m_gzip) done = readInflated(static_cast<uint8_t*>(buffer), count);
	else
	{
		m_file.read(static_cast<char*>(buffer), static_cast<std::streamsize>(count));
		done = static_cast<size_t>(m_file.gcount());
	}
	m_position += done;
	return done;
}

bool GzipInputFile::refill()
{
	// What igzip has not taken yet goes first (a member's start, say).
	const size_t kept = m_state->avail_in;
	std::memmove(m_in.data(), m_state->next_in, kept);
	m_file.read(reinterpret_cast<char*>(m_in.data() + kept), static_cast<std::streamsize>(m_in.size() - kept));
	const auto read = static_cast<size_t>(m_file.gcount());
	m_state->next_in = m_in.data();
	m_state->avail_in = static_cast<uint32_t>(kept + read);
	return read > 0;
}

bool GzipInputFile::nextMember()
{
	if (m_state->avail_in < 2) refill();
	// Whatever follows the last member is ignored, as zlib's gzread does.
	if (!startsGzipMember(m_state->next_in, m_state->avail_in)) return false;
	uint8_t* const nextIn = m_state->next_in;
	const uint32_t availIn = m_state->avail_in;
	isal_inflate_reset(m_state.get());
	m_state->next_in = nextIn;
	m_state->avail_in = availIn;
	m_state->crc_flag = ISAL_GZIP;
	return true;
}

size_t GzipInputFile::readInflated(uint8_t* out, size_t count)
{
	size_t done = 0;
	while (done < count && !m_ended)
	{
		if (m_state->block_state == ISAL_BLOCK_FINISH && !nextMember())
		{
			m_ended = true;
			break;
		}
		const bool fileLeft = m_state->avail_in > 0 || refill();
		const size_t chunk = std::min<size_t>(count - done, size_t{1} << 30);
		m_state->next_out = out + done;
		m_state->avail_out = static_cast<uint32_t>(chunk);
		const uint32_t inputBefore = m_state->avail_in;
		const int result = isal_inflate(m_state.get());
		if (result < 0) throw std::runtime_error(m_path + ": corrupt gzip data (igzip error " + std::to_string(result) + ")");
		const size_t produced = chunk - m_state->avail_out;
		done += produced;
		if (produced == 0 && m_state->block_state != ISAL_BLOCK_FINISH)
		{
			// Nothing more to come from a member that has not ended: cut
			// short. (And never a loop on input igzip will not take.)
			if (!fileLeft) throw std::runtime_error(m_path + ": gzip data cut short");
			if (m_state->avail_in == inputBefore) throw std::runtime_error(m_path + ": corrupt gzip data");
		}
	}
	return done;
}

size_t GzipInputFile::Write(const void*, size_t) { throw std::logic_error("GzipInputFile: written to"); }

uint64_t GzipInputFile::Seek(int64_t, mrpt::io::CStream::TSeekOrigin)
{
	throw std::logic_error("GzipInputFile: seek in a file read forward only");
}

uint64_t GzipInputFile::getTotalBytesCount() const
{
	// The file's size on disk, as MRPT's CFileGZInputStream gives it.
	return std::filesystem::file_size(m_path);
}

}  // namespace lvf::common
