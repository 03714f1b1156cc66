// openIniFile: an INI file checked line by line before MRPT's parser reads
// it, for what that parser skips or settles without a word (a line that is
// neither comment, section nor key, a key outside any section, a key given
// twice). The lines are read as MRPT reads them (MrptIniLines), so that the
// check and MRPT agree on what each line is.

#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/system/string_utils.h>

#include <fstream>
#include <map>
#include <optional>
#include <utility>

namespace lvf::common
{
namespace
{
/** `line` without the '\r' of a CRLF file. */
std::string withoutCarriageReturn(std::string line)
{
	if (!line.empty() && line.back() == '\r') line.pop_back();
	return line;
}

/** A line MRPT joins with the next: a '\' right before the line's end (not
 * before blanks), and not an @define line, whose value MRPT takes whole. */
bool endsWithContinuation(const std::string& line)
{
	const auto first = line.find_first_not_of(" \t");
	return !line.empty() && line.back() == '\\' && first != std::string::npos && line[first] != '@';
}

/** A file's lines as MRPT's parser sees them: a CRLF's '\r' and a first
 * line's UTF-8 mark dropped, a line ending in '\' joined with the next (a
 * long formula over several lines, as in MRPT's own example files). */
class MrptIniLines
{
   public:
	explicit MrptIniLines(const std::string& path) : m_in(path) {}

	struct Line
	{
		int number;	 //!< of its first physical line, from 1
		std::string text;
	};

	std::optional<Line> next()
	{
		std::string raw;
		if (!std::getline(m_in, raw)) return std::nullopt;
		Line line{++m_read, withoutCarriageReturn(raw)};
		if (line.number == 1 && line.text.rfind("\xEF\xBB\xBF", 0) == 0) line.text.erase(0, 3);
		for (std::string more; endsWithContinuation(line.text) && std::getline(m_in, more); m_read++)
		{
			line.text.pop_back();
			line.text += withoutCarriageReturn(more);
		}
		return line;
	}

   private:
	std::ifstream m_in;
	int m_read = 0;	 //!< physical lines read so far
};
}  // namespace

std::unique_ptr<mrpt::config::CConfigFile> openIniFile(const std::string& path)
{
	requireInputFile(path, "configuration file");
	MrptIniLines lines(path);
	bool inSection = false;
	// MRPT keeps the last of a key given twice in a section, without a word:
	// a pasted duplicate would silently change a setting.
	std::string section;
	std::map<std::pair<std::string, std::string>, int> firstLineOf;	// (section, key) -> line
	while (const auto line = lines.next())
	{
		const auto first = line->text.find_first_not_of(" \t\r");
		if (first == std::string::npos) continue;
		const std::string t = line->text.substr(first);
		if (t[0] == ';' || t[0] == '#' || t.rfind("//", 0) == 0 || t[0] == '@') continue;
		const std::string where = "line " + std::to_string(line->number);
		if (t[0] == '[')
		{
			const auto close = t.find(']');
			if (close == std::string::npos || close == 1)
				throw InputError(path, where, "malformed section header '" + t + "'");
			inSection = true;
			section = mrpt::system::trim(t.substr(1, close - 1));
			continue;
		}
		if (t.find('=') == std::string::npos || t[0] == '=')
			throw InputError(path, where, "expected 'key = value' or '[section]', got '" + t + "'");
		if (!inSection) throw InputError(path, where, "key outside of any [section]");
		const std::string key = mrpt::system::trim(t.substr(0, t.find('=')));
		// Keys and section names as MRPT compares them: case aside.
		const auto [earlier, isNew] = firstLineOf.try_emplace(
			{mrpt::system::lowerCase(section), mrpt::system::lowerCase(key)}, line->number);
		if (!isNew)
			throw InputError(path, where + ": [" + section + "] " + key,
				"given twice (first on line " + std::to_string(earlier->second) + ")");
	}
	try
	{
		return std::make_unique<mrpt::config::CConfigFile>(path);
	}
	catch (const std::exception& e)
	{
		// MRPT's own preprocessing (@define, ${name}, $env{}, $eval{})
		// refuses the file: its message names the line.
		throw InputError(path, "", exceptionMessage(e));
	}
}

}  // namespace lvf::common
