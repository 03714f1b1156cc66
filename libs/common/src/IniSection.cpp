#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/LikelyMeant.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/format.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace lvf::common
{
namespace
{
/** A key as MRPT's parser stores it may keep the blanks around it. */
std::string keyName(const std::string& stored) { return mrpt::system::trim(stored); }
}  // namespace

std::vector<std::string> keyNames(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	std::vector<std::string> keys;
	cfg.getAllKeys(section, keys);
	for (auto& k : keys) k = keyName(k);
	return keys;
}

std::string configSourceName(const mrpt::config::CConfigFileBase& cfg)
{
	if (const auto* f = dynamic_cast<const mrpt::config::CConfigFile*>(&cfg))
		return f->getAssociatedFile();
	return "<memory>";
}

IniSection::IniSection(
	const mrpt::config::CConfigFileBase& cfg, std::string section)
	: m_cfg(cfg), m_section(std::move(section)), m_source(configSourceName(cfg))
{
	// Keys as stored may carry the column padding writeOption adds (MRPT's
	// in-memory configs keep it); look them up by their trimmed names.
	std::vector<std::string> keys;
	m_cfg.getAllKeys(m_section, keys);
	for (const auto& stored : keys) m_storedKeys[keyName(stored)] = stored;
}

bool IniSection::has(const std::string& key)
{
	m_readKeys.insert(key);
	return m_storedKeys.count(key) > 0;
}

std::string IniSection::value(const std::string& key) const
{
	return m_cfg.read_string(m_section, m_storedKeys.at(key), "");
}

void IniSection::fail(const std::string& key, const std::string& what) const
{
	throw InputError(m_source, "[" + m_section + "] " + key, what);
}

double IniSection::number(
	const std::string& key, double minValue, double maxValue, bool integral)
{
	const std::string s = value(key);
	double v = 0;
	try
	{
		size_t used = 0;
		v = std::stod(s, &used);
		if (s.find_first_not_of(" \t", used) != std::string::npos)
			throw std::invalid_argument(s);
	}
	catch (const std::exception&)
	{
		fail(key, "'" + s + "' is not a number");
	}
	if (!std::isfinite(v)) fail(key, "'" + s + "' is not a finite number");
	if (integral && v != std::floor(v)) fail(key, "'" + s + "' is not an integer");
	if (v < minValue || v > maxValue)
		fail(
			key, mrpt::format(
					 "%s is out of range [%g, %g]", s.c_str(), minValue,
					 maxValue));
	return v;
}

double IniSection::real(
	const std::string& key, double defaultValue, double minValue,
	double maxValue)
{
	return has(key) ? number(key, minValue, maxValue, false) : defaultValue;
}

int IniSection::integer(
	const std::string& key, int defaultValue, int minValue, int maxValue)
{
	return has(key) ? static_cast<int>(number(key, minValue, maxValue, true))
					: defaultValue;
}

bool IniSection::flag(const std::string& key, bool defaultValue)
{
	if (!has(key)) return defaultValue;
	const std::string s = mrpt::system::lowerCase(value(key));
	if (s == "true" || s == "1" || s == "yes" || s == "on") return true;
	if (s == "false" || s == "0" || s == "no" || s == "off") return false;
	fail(key, "'" + s + "' is not a boolean (true/false)");
}

std::string IniSection::text(
	const std::string& key, const std::string& defaultValue)
{
	if (!has(key)) return defaultValue;
	return value(key);
}

std::vector<double> IniSection::reals(
	const std::string& key, const std::vector<double>& defaultValue)
{
	if (!has(key)) return defaultValue;
	std::string s = value(key);
	for (auto& c : s)
		if (c == ',' || c == '[' || c == ']') c = ' ';
	std::istringstream in(s);
	std::vector<double> out;
	std::string token;
	while (in >> token)
	{
		try
		{
			size_t used = 0;
			out.push_back(std::stod(token, &used));
			if (used != token.size()) throw std::invalid_argument(token);
		}
		catch (const std::exception&)
		{
			fail(key, "'" + token + "' is not a number");
		}
	}
	return out;
}

void IniSection::rejectUnknownKeys() const
{
	const std::vector<std::string> known(m_readKeys.begin(), m_readKeys.end());
	for (const auto& [name, stored] : m_storedKeys)
		if (!m_readKeys.count(name)) fail(name, "unknown key" + didYouMean(name, known));
}

void rejectKeysOfOtherSections(const mrpt::config::CConfigFileBase& cfg, const mrpt::config::CConfigFileBase& defaults)
{
	std::vector<std::string> sections;
	defaults.getAllSections(sections);
	std::map<std::string, std::vector<std::string>> keysOf;	 // every section's, once
	for (const auto& section : sections) keysOf[section] = keyNames(defaults, section);
	auto has = [](const std::vector<std::string>& keys, const std::string& key) {
		return std::find(keys.begin(), keys.end(), key) != keys.end();
	};
	for (const auto& section : sections)
	{
		const auto& own = keysOf[section];
		for (const auto& key : keyNames(cfg, section))
		{
			if (has(own, key)) continue;
			auto unknown = [&](const std::string& why) {
				return InputError(configSourceName(cfg), "[" + section + "] " + key, "unknown key (" + why + ")");
			};
			// Another section's key, as it is or misspelt (when the key's
			// own section has none it is likely to be).
			std::vector<std::string> nearOnes;
			for (const auto& other : sections)
			{
				const auto& theirs = keysOf[other];
				if (has(theirs, key)) throw unknown("it belongs in [" + other + "]");
				if (const auto meant = likelyMeant(key, theirs); !meant.empty())
					nearOnes.push_back("[" + other + "] " + meant);
			}
			if (nearOnes.size() == 1 && likelyMeant(key, own).empty())
				throw unknown("did you mean " + nearOnes.front() + "?");
		}
	}
}

void rejectUnknownSections(
	const mrpt::config::CConfigFileBase& cfg,
	const std::vector<std::string>& known)
{
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& s : sections)
		if (!s.empty() &&
			std::find(known.begin(), known.end(), s) == known.end())
			throw InputError(
				configSourceName(cfg), "[" + s + "]", "unknown section" + didYouMean(s, known));
}

}  // namespace lvf::common
