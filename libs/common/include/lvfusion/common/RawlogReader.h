#pragma once
// Reading a rawlog (either MRPT layout) object by object. MRPT's CRawlog
// loader prints its own multi-line errors and keeps going; here a corrupt or
// truncated file is one InputError naming the record.

#include <mrpt/serialization/CSerializable.h>

#include <memory>
#include <string>

namespace mrpt::serialization
{
class CArchive;
}

namespace lvf::common
{
class GzipInputFile;

/** The file's objects one at a time (observations, or actions and sensory
 * frames), for logs too long to hold: a real robot's, with its images. */
class RawlogReader
{
   public:
	/** Throws InputError if the file is missing. */
	explicit RawlogReader(const std::string& path);
	~RawlogReader();
	RawlogReader(const RawlogReader&) = delete;
	RawlogReader& operator=(const RawlogReader&) = delete;

	/** The next object, nullptr after the last. Throws InputError naming
	 * the record if it is not an MRPT object (corrupt, truncated, not a
	 * rawlog), and if the file holds none at all. */
	mrpt::serialization::CSerializable::Ptr next();

	/** How many objects next() has returned. */
	size_t count() const { return m_count; }

   private:
	std::string m_path;
	std::unique_ptr<GzipInputFile> m_file;  //!< GzipInputFile.h: as MRPT reads a rawlog, faster
	std::unique_ptr<mrpt::serialization::CArchive> m_archive;
	size_t m_count = 0;
};

/** The name a run's outputs take from its rawlog: the file name without
 * `.rawlog`, `.rawlog.gz` or `.gz` ("run.rawlog.gz" -> "run"), or without
 * whatever other extension it has. */
std::string rawlogName(const std::string& path);

}  // namespace lvf::common
