#pragma once
// A gzip file written a member at a time with ISA-L's igzip, every write
// checked: the one way lvfusion writes MRPT's gzip archives (rawlogs
// through GzWriterThread.h, grids through saveGrid).
//
// Written by hand because neither MRPT nor zlib offers both halves: MRPT's
// CFileGZOutputStream drops the result of gzclose(), which writes what zlib
// still holds -- on a full disk the whole of a small file, the tail of a
// large one -- so its outputs can end short without a word; and zlib
// deflates a rawlog of images at a seventh of igzip's speed to about the
// same size (measurements.md, sessions 46 and 47). Each buffer becomes one
// gzip member (igzip's one-shot compression); gzip allows a file of
// several, and zlib's gzread (MRPT's CFileGZInputStream, so every MRPT
// tool), zcat and Python read them as one stream.

#include <lvfusion/common/WrittenFiles.h>
#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lvf::common
{
/** The bytes MRPT's archive writes for `object` (a rawlog entry, a grid). */
std::vector<uint8_t> archived(const mrpt::serialization::CSerializable& object);

class GzipMemberFile
{
   public:
	/** Opens `path` for igzip's `level` (0 fastest .. 3 smallest);
	 * InputError naming it if it cannot be opened. */
	GzipMemberFile(const std::string& path, int level);
	GzipMemberFile(const GzipMemberFile&) = delete;
	GzipMemberFile& operator=(const GzipMemberFile&) = delete;
	// (~OutputFile closes silently: close() is what reports.)

	/** Compresses `bytes` as one gzip member and writes it; InputError
	 * naming the file if it cannot be written (a full disk). */
	void writeMember(const std::vector<uint8_t>& bytes);
	/** Closes; InputError naming the file if any of it was not written. */
	void close() { m_file.close(); }

   private:
	OutputFile m_file;
	const int m_level;
	std::vector<uint8_t> m_levelBuffer;	 //!< igzip's working memory for m_level
	std::vector<uint8_t> m_compressed;	//!< a member, compressed (kept to reuse its memory)
};

}  // namespace lvf::common
