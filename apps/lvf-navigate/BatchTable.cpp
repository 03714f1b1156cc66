#include "BatchTable.h"

#include <mrpt/core/format.h>

#include <fstream>
#include <map>
#include <tuple>

namespace lvf::apps
{
void writeBatchCsv(const std::vector<BatchRow>& rows, const std::string& path)
{
	std::ofstream csv(path);
	csv << "room_kind,world,method,sensing,outcome,reached,collisions,time_s,path_m,"
		   "final_distance_m,min_clearance_m,cycle_ms,detail\n";
	for (const auto& r : rows)
	{
		const auto& m = r.metrics;
		std::string detail = m.detail;
		for (auto& ch : detail)
			if (ch == '"') ch = '\'';
		csv << mrpt::format(
			"%s,%s,%s,%s,%s,%d,%d,%.2f,%.3f,%.3f,%.4f,%.2f,\"%s\"\n", r.roomKind.c_str(),
			r.world.c_str(), r.method.c_str(), r.sensing.c_str(), outcomeName(m.outcome),
			m.reached() ? 1 : 0, m.collisions, m.time, m.pathLength, m.finalDistance,
			m.minClearance, m.meanCycleMs, detail.c_str());
	}
}

void printBatchTable(const std::vector<BatchRow>& rows, std::ostream& out)
{
	struct Group
	{
		int runs = 0, reached = 0, collided = 0;
		double time = 0, path = 0, clearance = 0, cycle = 0;
	};
	// Sorted by room kind, then in the order methods and sensing came.
	std::map<std::tuple<std::string, std::string, std::string>, Group> groups;
	for (const auto& r : rows)
	{
		auto& g = groups[{r.roomKind, r.method, r.sensing}];
		const auto& m = r.metrics;
		g.runs++;
		g.collided += m.collisions;
		g.clearance += m.minClearance;
		g.cycle += m.meanCycleMs;
		if (!m.reached()) continue;
		g.reached++;
		g.time += m.time;
		g.path += m.pathLength;
	}
	out << mrpt::format(
		"%-10s %-20s %-6s %5s %9s %9s %10s %10s %12s %9s\n", "rooms", "method", "sense", "runs",
		"reached", "collided", "time [s]", "path [m]", "min clr [m]", "cycle ms");
	for (const auto& [key, g] : groups)
	{
		const auto& [kind, method, sensing] = key;
		const double n = g.runs, k = std::max(1, g.reached);
		out << mrpt::format(
			"%-10s %-20s %-6s %5d %8.1f%% %8.1f%% %10.1f %10.2f %12.3f %9.1f\n", kind.c_str(),
			method.c_str(), sensing.c_str(), g.runs, 100.0 * g.reached / n, 100.0 * g.collided / n,
			g.time / k, g.path / k, g.clearance / n, g.cycle / n);
	}
	out << "(time and path: means over the reached runs; min clr: mean over all runs of the "
		   "smallest clearance, negative when it hit)\n";
}

}  // namespace lvf::apps
