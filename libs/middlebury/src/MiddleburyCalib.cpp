#include <lvfusion/middlebury/MiddleburyCalib.h>

#include <lvfusion/common/InputError.h>
#include <mrpt/core/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

using lvf::common::InputError;

namespace lvf::middlebury
{
namespace
{
std::string trim(const std::string& s)
{
	const auto first = s.find_first_not_of(" \t\r");
	if (first == std::string::npos) return "";
	return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

struct Field
{
	std::string value;
	int line = 0;
};

/** The "key=value" lines of calib.txt, and their values parsed completely
 * (std::stod alone would read "3x" as 3). */
class CalibFields
{
   public:
	explicit CalibFields(const std::string& path) : m_path(path)
	{
		std::ifstream in(path);
		if (!in) throw InputError(path, "", "cannot open calibration file");
		int lineNumber = 0;
		for (std::string line; std::getline(in, line);)
		{
			lineNumber++;
			if (trim(line).empty()) continue;
			const auto eq = line.find('=');
			const std::string where = "line " + std::to_string(lineNumber);
			if (eq == std::string::npos || trim(line.substr(0, eq)).empty())
				throw InputError(path, where, "expected 'key=value', got '" + trim(line) + "'");
			const std::string key = trim(line.substr(0, eq));
			if (m_fields.count(key))
				throw InputError(path, where + ": " + key, mrpt::format(
					"given twice (first on line %d)", m_fields[key].line));
			m_fields[key] = {trim(line.substr(eq + 1)), lineNumber};
		}
	}

	/** "line N: key", for messages about a field that exists. */
	std::string where(const std::string& key) const
	{
		return "line " + std::to_string(get(key).line) + ": " + key;
	}

	bool has(const std::string& key) const { return m_fields.count(key) != 0; }

	double number(const std::string& key) const { return parse(key, get(key).value); }

	int integer(const std::string& key) const
	{
		const double v = number(key);
		if (v != std::floor(v) || v < 1 || v > 65536)
			throw InputError(m_path, where(key), "'" + get(key).value + "' is not a positive integer");
		return static_cast<int>(v);
	}

	/** "[ a b c ; d e f ; g h i ]", row by row. */
	std::array<double, 9> matrix(const std::string& key) const
	{
		std::string s = get(key).value;
		if (s.size() < 2 || s.front() != '[' || s.back() != ']')
			throw InputError(m_path, where(key), "'" + s + "' is not a matrix [a b c; d e f; g h i]");
		for (auto& c : s)
			if (c == '[' || c == ']' || c == ';') c = ' ';
		std::istringstream in(s);
		std::vector<std::string> tokens;
		for (std::string token; in >> token;) tokens.push_back(token);
		if (tokens.size() != 9)
			throw InputError(m_path, where(key), mrpt::format(
				"'%s' is not a 3x3 matrix (%zu numbers)", get(key).value.c_str(), tokens.size()));
		std::array<double, 9> m{};
		for (size_t i = 0; i < 9; i++) m[i] = parse(key, tokens[i]);
		return m;
	}

   private:
	const Field& get(const std::string& key) const
	{
		const auto it = m_fields.find(key);
		if (it == m_fields.end()) throw InputError(m_path, key, "missing field");
		return it->second;
	}

	double parse(const std::string& key, const std::string& text) const
	{
		double v = 0;
		try
		{
			size_t used = 0;
			v = std::stod(text, &used);
			if (used != text.size()) throw std::invalid_argument(text);
		}
		catch (const std::exception&)
		{
			throw InputError(m_path, where(key), "'" + text + "' is not a number");
		}
		if (!std::isfinite(v)) throw InputError(m_path, where(key), "'" + text + "' is not a finite number");
		return v;
	}

	std::string m_path;
	std::map<std::string, Field> m_fields;
};

bool near(double a, double b, double tolerance) { return std::abs(a - b) <= tolerance; }

}  // namespace

mrpt::img::TCamera MiddleburyCalib::leftCamera() const
{
	mrpt::img::TCamera cam;
	cam.ncols = static_cast<uint32_t>(width);
	cam.nrows = static_cast<uint32_t>(height);
	cam.setIntrinsicParamsFromValues(f, f, cx0, cy);
	return cam;
}

mrpt::img::TCamera MiddleburyCalib::rightCamera() const
{
	auto cam = leftCamera();
	cam.setIntrinsicParamsFromValues(f, f, cx1, cy);
	return cam;
}

MiddleburyCalib readMiddleburyCalib(const std::string& path)
{
	CalibFields fields(path);
	// Every field first, so that a missing one is named before any
	// consistency check runs.
	const auto cam0 = fields.matrix("cam0");
	const auto cam1 = fields.matrix("cam1");
	MiddleburyCalib c;
	c.doffs = fields.number("doffs");
	const double baselineMm = fields.number("baseline");
	c.width = fields.integer("width");
	c.height = fields.integer("height");
	if (fields.has("ndisp")) c.ndisp = fields.integer("ndisp");

	// The importer's geometry (one f, one cy, Z = b f / (d + doffs)) holds
	// only for a rectified pair with square pixels: check that it is one.
	for (const auto& [key, m] : {std::pair{"cam0", cam0}, std::pair{"cam1", cam1}})
	{
		const std::string where = fields.where(key);
		if (!(m[0] > 0) || !near(m[0], m[4], 1e-6 * m[0]))
			throw InputError(path, where, mrpt::format(
				"fx %g and fy %g must be equal and positive", m[0], m[4]));
		if (m[1] != 0 || m[3] != 0 || m[6] != 0 || m[7] != 0 || m[8] != 1)
			throw InputError(path, where, "not an intrinsic matrix [f 0 cx; 0 f cy; 0 0 1]");
	}
	if (!near(cam0[0], cam1[0], 1e-6 * cam0[0]) || !near(cam0[5], cam1[5], 1e-3))
		throw InputError(path, fields.where("cam1"), mrpt::format(
			"f %g and cy %g differ from cam0's (%g, %g): not a rectified pair",
			cam1[0], cam1[5], cam0[0], cam0[5]));
	c.f = cam0[0];
	c.cx0 = cam0[2];
	c.cx1 = cam1[2];
	c.cy = cam0[5];
	if (!near(c.doffs, c.cx1 - c.cx0, 1e-2))
		throw InputError(path, fields.where("doffs"), mrpt::format(
			"%g, but cam1's cx - cam0's cx is %g", c.doffs, c.cx1 - c.cx0));
	if (!(baselineMm > 0))
		throw InputError(path, fields.where("baseline"), "must be > 0 [mm]");
	c.baseline = baselineMm / 1000.0;
	return c;
}

}  // namespace lvf::middlebury
