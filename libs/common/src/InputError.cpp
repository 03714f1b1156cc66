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

}  // namespace lvf::common
