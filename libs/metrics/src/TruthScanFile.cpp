#include <lvfusion/common/InputError.h>
#include <lvfusion/metrics/TruthScanFile.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace lvf::metrics
{
std::vector<TruthScan> readTruthScans(const std::string& path)
{
	lvf::common::requireInputFile(path, "truth scan file");
	std::ifstream in(path);
	std::vector<TruthScan> out;
	std::string line;
	std::getline(in, line);	 // header
	for (int lineNumber = 2; std::getline(in, line); lineNumber++)
	{
		if (line.empty()) continue;
		std::istringstream fields(line);
		std::string field;
		TruthScan t;
		try
		{
			std::getline(fields, field, ',');  // frame index
			std::getline(fields, field, ',');
			t.timestamp = std::stod(field);
			while (std::getline(fields, field, ','))
				t.ranges.push_back(field == "inf" ? INFINITY : std::stof(field));
		}
		catch (const std::exception&)
		{
			throw lvf::common::InputError(
				path, "line " + std::to_string(lineNumber), "malformed value '" + field + "'");
		}
		if (!out.empty() && t.ranges.size() != out.front().ranges.size())
			throw lvf::common::InputError(
				path, "line " + std::to_string(lineNumber), "number of ranges differs from line 2");
		out.push_back(std::move(t));
	}
	return out;
}

const TruthScan* findTruthScan(const std::vector<TruthScan>& scans, double timestamp)
{
	for (const auto& s : scans)
		if (std::abs(s.timestamp - timestamp) < 1e-4) return &s;
	return nullptr;
}

}  // namespace lvf::metrics
