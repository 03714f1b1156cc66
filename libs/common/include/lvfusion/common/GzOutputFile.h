#pragma once
// A gzip file for MRPT's archives (rawlogs, .gridmap.gz) whose close()
// says whether the file was written. MRPT's CFileGZOutputStream drops the
// result of gzclose(), which writes what zlib still holds -- on a full
// disk the whole of a small file, the tail of a large one -- so its
// outputs can end short without a word. Written by hand for that alone;
// the format is zlib's gzip, as MRPT's own stream writes it.

#include <mrpt/io/CStream.h>
#include <mrpt/serialization/CSerializable.h>

#include <string>

namespace lvf::common
{
class GzOutputFile : public mrpt::io::CStream
{
   public:
	/** Opens `path` for writing at zlib's `level` (0-9); InputError naming
	 * it if that cannot be done. */
	explicit GzOutputFile(const std::string& path, int level = 1);
	/** Closes the file if close() was not called, silently (an exception
	 * is on its way, or the file is being abandoned). */
	~GzOutputFile() override;
	GzOutputFile(const GzOutputFile&) = delete;
	GzOutputFile& operator=(const GzOutputFile&) = delete;

	/** Serializes `object` as MRPT's archives do (a rawlog entry, a
	 * grid); InputError naming the file if it cannot be written. */
	void writeObject(const mrpt::serialization::CSerializable& object);

	/** Writes out what zlib holds and closes; InputError naming the file
	 * if any of it could not be written (a full disk). */
	void close();

	size_t Write(const void* buffer, size_t count) override;
	size_t Read(void* buffer, size_t count) override;
	uint64_t Seek(int64_t offset, mrpt::io::CStream::TSeekOrigin origin = sFromBeginning) override;
	uint64_t getTotalBytesCount() const override;
	uint64_t getPosition() const override;
	std::string getStreamDescription() const override;

   private:
	std::string m_path;
	void* m_file = nullptr;	 // zlib's gzFile (kept out of this header)
};

}  // namespace lvf::common
