#include <lvfusion/common/InputError.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace lvf::common
{
namespace
{
std::string formatInputError(
	const std::string& source, const std::string& where,
	const std::string& what)
{
	std::string line = source;
	if (!where.empty()) line += ": " + where;
	line += ": " + what;
	// One line, always: multi-line messages (e.g. from parsers) are folded.
	for (auto& c : line)
		if (c == '\n' || c == '\r') c = ' ';
	return line;
}
}  // namespace

InputError::InputError(
	const std::string& source, const std::string& where,
	const std::string& what)
	: std::runtime_error(formatInputError(source, where, what)),
	  m_source(source)
{
}

void requireInputFile(const std::string& path, const std::string& what)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	const auto status = fs::status(path, ec);
	if (!fs::exists(status)) throw InputError(path, "", what + " not found");
	if (fs::is_directory(status)) throw InputError(path, "", what + " is a folder, not a file");
	if (!std::ifstream(path)) throw InputError(path, "", std::string("cannot read it: ") + std::strerror(errno));
}

void requireRegularInputFile(const std::string& path, const std::string& what)
{
	requireInputFile(path, what);
	std::error_code ec;
	if (!std::filesystem::is_regular_file(path, ec))
		throw InputError(path, "", what + " is not a regular file (a device or pipe): MRPT reads it from a file only");
}

std::string exceptionMessage(const std::exception& e)
{
	const std::string s = e.what();
	const std::string label = "Message:", banner = "==== MRPT exception ====";
	size_t from = 0;
	if (const auto message = s.find(label); message != std::string::npos)
		from = message + label.size();
	else if (s.rfind(banner, 0) == 0)
		from = banner.size();
	from = s.find_first_not_of(" \n", from);
	if (from == std::string::npos) return s;
	const auto end = s.find('\n', from);
	return s.substr(from, end == std::string::npos ? std::string::npos : end - from);
}

}  // namespace lvf::common
