#pragma once
// A rawlog file read as MRPT's CFileGZInputStream reads it -- gzip (one
// member or several, one after another) or not compressed at all -- but
// inflated with ISA-L's igzip, three times as fast as zlib's gzread. Reading
// was a third of a long lvf-fuse run's main thread, which reads its input
// twice (measurements.md, session 47). Read-only, forward only.

#include <mrpt/io/CStream.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

struct inflate_state;

namespace lvf::common
{
class GzipInputFile : public mrpt::io::CStream
{
   public:
	/** Opens `path` (InputError naming it if it cannot be read). */
	explicit GzipInputFile(const std::string& path);
	~GzipInputFile() override;
	GzipInputFile(const GzipInputFile&) = delete;
	GzipInputFile& operator=(const GzipInputFile&) = delete;

	/** Up to `count` bytes of the file's content (inflated); fewer only at
	 * its end. Throws std::runtime_error where a gzip member is corrupt or
	 * cut short. */
	size_t Read(void* buffer, size_t count) override;
	/** The bytes of content read so far. */
	uint64_t getPosition() const override { return m_position; }

	size_t Write(const void* buffer, size_t count) override;
	uint64_t Seek(int64_t offset, mrpt::io::CStream::TSeekOrigin origin = sFromBeginning) override;
	uint64_t getTotalBytesCount() const override;
	std::string getStreamDescription() const override { return "rawlog file '" + m_path + "'"; }

   private:
	/** Reads more of the file into m_in once igzip has taken all of it;
	 * false at the file's end. */
	bool refill();
	/** After a member's end: true if another follows (and is begun). */
	bool nextMember();
	size_t readInflated(uint8_t* out, size_t count);

	std::string m_path;
	std::ifstream m_file;
	bool m_gzip = false;
	bool m_ended = false;  //!< the last member's end has been read
	std::unique_ptr<inflate_state> m_state;
	std::vector<uint8_t> m_in;	//!< the file's bytes, a buffer at a time
	uint64_t m_position = 0;
};

}  // namespace lvf::common
