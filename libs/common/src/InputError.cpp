#include <lvfusion/common/InputError.h>

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

}  // namespace lvf::common
