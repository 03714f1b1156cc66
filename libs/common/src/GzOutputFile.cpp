#include <lvfusion/common/GzOutputFile.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/WrittenFiles.h>

#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <algorithm>
#include <stdexcept>

namespace lvf::common
{
namespace
{
gzFile asGz(void* file) { return static_cast<gzFile>(file); }
}  // namespace

GzOutputFile::GzOutputFile(const std::string& path, int level) : m_path(path)
{
	m_file = gzopen(path.c_str(), ("wb" + std::to_string(level)).c_str());
	if (!m_file) throw InputError(path, "", "cannot open for writing");
}

GzOutputFile::~GzOutputFile()
{
	if (m_file) gzclose(asGz(m_file));
}

void GzOutputFile::writeObject(const mrpt::serialization::CSerializable& object)
{
	try
	{
		auto archive = mrpt::serialization::archiveFrom(*this);
		archive << object;
	}
	catch (const InputError&)
	{
		throw;
	}
	catch (const std::exception&)
	{
		// MRPT's archive throws on a short write with its own stack of
		// frames; one line is what every bad input and output gets here.
		requireWritten(false, m_path);
	}
}

void GzOutputFile::close()
{
	if (!m_file) return;
	const int result = gzclose(asGz(m_file));
	m_file = nullptr;
	requireWritten(result == Z_OK, m_path);
}

size_t GzOutputFile::Write(const void* buffer, size_t count)
{
	if (!m_file) throw InputError(m_path, "", "written after it was closed");
	// gzwrite takes an unsigned count: a larger buffer goes in pieces.
	const auto* bytes = static_cast<const char*>(buffer);
	size_t written = 0;
	while (written < count)
	{
		const unsigned piece = static_cast<unsigned>(std::min<size_t>(count - written, 1u << 30));
		const int n = gzwrite(asGz(m_file), bytes + written, piece);
		if (n <= 0) break;	// MRPT's archive reports the short count
		written += static_cast<size_t>(n);
	}
	return written;
}

size_t GzOutputFile::Read(void*, size_t) { throw std::logic_error("GzOutputFile: read from an output file"); }

uint64_t GzOutputFile::Seek(int64_t, mrpt::io::CStream::TSeekOrigin)
{
	throw std::logic_error("GzOutputFile: seek in a gzip output file");
}

uint64_t GzOutputFile::getTotalBytesCount() const
{
	throw std::logic_error("GzOutputFile: the size of a gzip output file");
}

uint64_t GzOutputFile::getPosition() const
{
	return m_file ? static_cast<uint64_t>(gztell(asGz(m_file))) : 0;
}

std::string GzOutputFile::getStreamDescription() const { return "gzip output file '" + m_path + "'"; }

}  // namespace lvf::common
