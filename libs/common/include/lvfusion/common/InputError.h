#pragma once
// The one exception type for "the user gave us something we cannot use":
// a bad file, key, value or record. Apps turn it into a single line on stderr
// and exit status 2 (see AppMain.h); anything else is a bug in lvfusion.

#include <stdexcept>
#include <string>

namespace lvf::common
{
class InputError : public std::runtime_error
{
   public:
	/** @param source file name (or "--option" for command-line values)
	 *  @param where  key, line or record inside the source, may be empty
	 *  @param what   what is wrong, phrased for the user */
	InputError(
		const std::string& source, const std::string& where,
		const std::string& what);

	const std::string& source() const { return m_source; }

   private:
	std::string m_source;
};

/** Throws InputError naming `path` unless it is a file that can be opened
 * for reading: "`what` not found", "a folder, not a `what`" or "cannot read
 * it: reason". (A folder opens as an empty stream, so reading it would
 * look like an empty file.) */
void requireInputFile(const std::string& path, const std::string& what);

/** requireInputFile, and a regular file: MRPT's (gzip) stream reader asks
 * a file's size first, which a device or a pipe has not. */
void requireRegularInputFile(const std::string& path, const std::string& what);

/** The line of an exception's text that says what went wrong. MRPT's
 * exceptions open with a "==== MRPT exception ====" banner and end with a
 * call stack; some put the message after "Message:". */
std::string exceptionMessage(const std::exception& e);

}  // namespace lvf::common
