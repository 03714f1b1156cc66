#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lvf::common
{
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
}

bool IniSection::has(const std::string& key)
{
	m_readKeys.insert(key);
	return m_cfg.keyExists(m_section, key);
}

void IniSection::fail(const std::string& key, const std::string& what) const
{
	throw InputError(m_source, "[" + m_section + "] " + key, what);
}

double IniSection::real(
	const std::string& key, double defaultValue, double minValue,
	double maxValue)
{
	if (!has(key)) return defaultValue;
	const std::string s = m_cfg.read_string(m_section, key, "");
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
	if (v < minValue || v > maxValue)
		fail(
			key, mrpt::format(
					 "%s is out of range [%g, %g]", s.c_str(), minValue,
					 maxValue));
	return v;
}

int IniSection::integer(
	const std::string& key, int defaultValue, int minValue, int maxValue)
{
	if (!has(key)) return defaultValue;
	const std::string s = m_cfg.read_string(m_section, key, "");
	long v = 0;
	try
	{
		size_t used = 0;
		v = std::stol(s, &used);
		if (s.find_first_not_of(" \t", used) != std::string::npos)
			throw std::invalid_argument(s);
	}
	catch (const std::exception&)
	{
		fail(key, "'" + s + "' is not an integer");
	}
	if (v < minValue || v > maxValue)
		fail(
			key, mrpt::format(
					 "%s is out of range [%d, %d]", s.c_str(), minValue,
					 maxValue));
	return static_cast<int>(v);
}

bool IniSection::flag(const std::string& key, bool defaultValue)
{
	if (!has(key)) return defaultValue;
	std::string s = m_cfg.read_string(m_section, key, "");
	std::transform(s.begin(), s.end(), s.begin(), ::tolower);
	if (s == "true" || s == "1" || s == "yes" || s == "on") return true;
	if (s == "false" || s == "0" || s == "no" || s == "off") return false;
	fail(key, "'" + s + "' is not a boolean (true/false)");
}

std::string IniSection::text(
	const std::string& key, const std::string& defaultValue)
{
	if (!has(key)) return defaultValue;
	return m_cfg.read_string(m_section, key, defaultValue);
}

std::vector<double> IniSection::reals(
	const std::string& key, const std::vector<double>& defaultValue)
{
	if (!has(key)) return defaultValue;
	std::string s = m_cfg.read_string(m_section, key, "");
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
	std::vector<std::string> keys;
	m_cfg.getAllKeys(m_section, keys);
	for (const auto& k : keys)
		if (!m_readKeys.count(k)) fail(k, "unknown key");
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
				configSourceName(cfg), "[" + s + "]", "unknown section");
}

}  // namespace lvf::common
