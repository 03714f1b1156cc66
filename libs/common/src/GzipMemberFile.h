#pragma once
// A gzip file written a member at a time with libdeflate, every write
// checked: the one way lvfusion writes MRPT's gzip archives (rawlogs
// through GzWriterThread.h, grids through saveGrid).
//
// Written by hand because neither MRPT nor zlib offers both halves: MRPT's
// CFileGZOutputStream drops the result of gzclose(), which writes what zlib
// still holds -- on a full disk the whole of a small file, the tail of a
// large one -- so its outputs can end short without a word; and zlib's
// stream deflates a rawlog of images at a third of libdeflate's speed
// (measurements.md, session 46). libdeflate compresses whole buffers, so
// each buffer becomes one gzip member; gzip allows a file of several, and
// zlib's gzread (MRPT's CFileGZInputStream, so every MRPT tool), zcat and
// Python read them as one stream.

#include <lvfusion/common/WrittenFiles.h>
#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct libdeflate_compressor;

namespace lvf::common
{
/** The bytes MRPT's archive writes for `object` (a rawlog entry, a grid). */
std::vector<uint8_t> archived(const mrpt::serialization::CSerializable& object);

class GzipMemberFile
{
   public:
	/** Opens `path` for `level` (1 fastest .. 12 smallest); InputError
	 * naming it if it cannot be opened. */
	GzipMemberFile(const std::string& path, int level);
	~GzipMemberFile();	// closes silently (close() reports)
	GzipMemberFile(const GzipMemberFile&) = delete;
	GzipMemberFile& operator=(const GzipMemberFile&) = delete;

	/** Compresses `bytes` as one gzip member and writes it; InputError
	 * naming the file if it cannot be written (a full disk). */
	void writeMember(const std::vector<uint8_t>& bytes);
	/** Closes; InputError naming the file if any of it was not written. */
	void close() { m_file.close(); }

   private:
	struct FreeCompressor
	{
		void operator()(libdeflate_compressor* c) const;
	};

	OutputFile m_file;
	std::unique_ptr<libdeflate_compressor, FreeCompressor> m_compressor;
	std::vector<uint8_t> m_compressed;	//!< a member, compressed (kept to reuse its memory)
};

}  // namespace lvf::common
