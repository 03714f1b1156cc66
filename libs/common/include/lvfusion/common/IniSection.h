#pragma once
// Strict reading of one INI section in MRPT's CConfigFile style.
//
// MRPT's read_double()/read_int() accept "abc" as 0 and ignore unknown keys;
// for a user that means a typo silently falls back to a default. IniSection
// parses every value completely, checks its range, remembers which keys were
// read, and rejectUnknownKeys() then names any key nobody asked for.

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <memory>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace lvf::common
{
class IniSection
{
   public:
	IniSection(const mrpt::config::CConfigFileBase& cfg, std::string section);

	double real(
		const std::string& key, double defaultValue,
		double minValue = -1e300, double maxValue = 1e300);
	int integer(
		const std::string& key, int defaultValue, int minValue = -2147483647,
		int maxValue = 2147483647);
	bool flag(const std::string& key, bool defaultValue);
	std::string text(const std::string& key, const std::string& defaultValue);
	/** A whitespace- or comma-separated list of numbers, e.g. "0.1 -0.2 0". */
	std::vector<double> reals(
		const std::string& key, const std::vector<double>& defaultValue);

	/** Throws InputError naming the first key in the section not read. */
	void rejectUnknownKeys() const;

	const std::string& section() const { return m_section; }
	/** "file.ini" or "<memory>" when the config has no file. */
	const std::string& sourceName() const { return m_source; }

   private:
	bool has(const std::string& key);
	/** The raw text of a key has() found. */
	std::string value(const std::string& key) const;
	/** The value of `key`, parsed completely and range-checked. */
	double number(
		const std::string& key, double minValue, double maxValue,
		bool integral);
	[[noreturn]] void fail(const std::string& key, const std::string& what) const;

	const mrpt::config::CConfigFileBase& m_cfg;
	std::string m_section;
	std::string m_source;
	std::set<std::string> m_readKeys;
	std::map<std::string, std::string> m_storedKeys;  // trimmed name -> key as stored
};

/** For options spread over several sections (`defaults`: every key in its
 * section, as saveToConfigFile writes them): throws InputError naming the
 * first key of `cfg` that is not in its own section but in another -- as
 * it is, or misspelt (likelyMeant) where its own section has no key it is
 * likely to mean -- and where it belongs: the likeliest slip after a typo.
 * Other unknown keys are left to IniSection::rejectUnknownKeys. */
void rejectKeysOfOtherSections(
	const mrpt::config::CConfigFileBase& cfg, const mrpt::config::CConfigFileBase& defaults);

/** The same for an options class whose `section` names the first of its
 * sections: `defaults` are what Options() saves there. */
template <class Options>
void rejectKeysOfOtherSections(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	mrpt::config::CConfigFileMemory defaults;
	Options().saveToConfigFile(defaults, section);
	rejectKeysOfOtherSections(cfg, defaults);
}

/** The names of the keys of `section` in `cfg` (blanks around them, which
 * MRPT's parser may keep, trimmed). */
std::vector<std::string> keyNames(const mrpt::config::CConfigFileBase& cfg, const std::string& section);

/** Throws InputError naming the first section of `cfg` not in `known`
 * (and the one likely meant). */
void rejectUnknownSections(
	const mrpt::config::CConfigFileBase& cfg,
	const std::vector<std::string>& known);

/** Opens an INI file after checking what MRPT's parser silently skips: every
 * line must be blank, a comment (; # //), an MRPT directive (@...), a
 * "[section]" or a "key = value" inside a section. Throws InputError naming
 * the file and line otherwise, or if the file cannot be read. */
std::unique_ptr<mrpt::config::CConfigFile> openIniFile(const std::string& path);

/** The file behind a config object, or "<memory>". */
std::string configSourceName(const mrpt::config::CConfigFileBase& cfg);

}  // namespace lvf::common

namespace lvf::common
{
/** Writes `key = value  // comment` with the column widths every lvfusion
 * option uses, so that --dump-config output lines up. */
template <typename T>
void writeOption(
	mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, const T& value, const std::string& comment)
{
	cfg.write(section, key, value, 28, 14, comment);
}
}  // namespace lvf::common
