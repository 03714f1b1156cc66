#pragma once
// Output files that say when they could not be written. A full disk (or a
// folder gone) must not leave a short CSV or picture among outputs the run
// then reports as written: each writer checks, and the app's one line
// names the file (InputError, exit status 2; the staged outputs are not
// committed, StagedOutputFiles.h).

#include <opencv2/core.hpp>

#include <fstream>
#include <string>

namespace lvf::common
{
/** Throws InputError naming `path` ("cannot be written (disk full?)")
 * unless `written`. */
void requireWritten(bool written, const std::string& path);

/** The picture encoded as its extension says (as cv::imwrite would: the
 * same bytes), and InputError naming the file if it cannot be written. */
void writeImage(const std::string& path, const cv::Mat& image);

/** A file being written (a std::ofstream) that keeps its path, so that
 * opening and closing it can name it. */
class OutputFile : public std::ofstream
{
   public:
	OutputFile() = default;
	explicit OutputFile(const std::string& path, std::ios::openmode mode = std::ios::out) { open(path, mode); }

	/** Opens `path`; InputError naming it if it cannot be opened for
	 * writing. */
	void open(const std::string& path, std::ios::openmode mode = std::ios::out);
	/** Closes, and InputError naming the file if any of it could not be
	 * written. (It hides std::ofstream::close: call it on an OutputFile.) */
	void close();
	/** The path it was opened with. */
	const std::string& path() const { return m_path; }

   private:
	std::string m_path;
};

/** Writes `text` as the whole of the file at `path`; InputError naming it
 * if that fails. */
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace lvf::common
