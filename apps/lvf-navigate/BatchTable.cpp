#include "BatchTable.h"

#include <lvfusion/common/WrittenFiles.h>
#include <mrpt/core/format.h>

#include <map>
#include <set>
#include <tuple>

namespace lvf::apps
{
void writeBatchCsv(const std::vector<BatchRow>& rows, const std::string& path)
{
	lvf::common::OutputFile csv(path);
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
	csv.close();
}

namespace
{
/** Per (room kind, sensing), the worlds every method run there reached:
 * the methods' paths compare fairly only over the same worlds (a method
 * that fails the hard rooms would otherwise look short). */
std::map<std::pair<std::string, std::string>, std::set<std::string>> worldsAllReached(
	const std::vector<BatchRow>& rows)
{
	std::map<std::pair<std::string, std::string>, std::set<std::string>> methods;
	std::map<std::tuple<std::string, std::string, std::string>, std::set<std::string>> reachedBy;
	for (const auto& r : rows)
	{
		methods[{r.roomKind, r.sensing}].insert(r.method);
		if (r.metrics.reached()) reachedBy[{r.roomKind, r.sensing, r.world}].insert(r.method);
	}
	std::map<std::pair<std::string, std::string>, std::set<std::string>> common;
	for (const auto& [key, by] : reachedBy)
	{
		const auto& [kind, sensing, world] = key;
		if (by == methods[{kind, sensing}]) common[{kind, sensing}].insert(world);
	}
	return common;
}
}  // namespace

void printBatchTable(const std::vector<BatchRow>& rows, std::ostream& out)
{
	struct Group
	{
		int runs = 0, reached = 0, collided = 0, common = 0;
		double time = 0, path = 0, commonPath = 0, clearance = 0, cycle = 0;
	};
	const auto common = worldsAllReached(rows);
	// Sorted by room kind, then method, then sensing, each by name.
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
		if (const auto c = common.find({r.roomKind, r.sensing}); c != common.end() && c->second.count(r.world))
			g.common++, g.commonPath += m.pathLength;
	}
	out << mrpt::format(
		"%-10s %-20s %-6s %5s %9s %9s %10s %10s %15s %12s %9s\n", "rooms", "method", "sense",
		"runs", "reached", "collided", "time [s]", "path [m]", "path, all [m]", "min clr [m]",
		"cycle ms");
	for (const auto& [key, g] : groups)
	{
		const auto& [kind, method, sensing] = key;
		const double n = g.runs, k = std::max(1, g.reached);
		const std::string commonPath =
			g.common ? mrpt::format("%.3f (%d)", g.commonPath / g.common, g.common) : std::string("-");
		out << mrpt::format(
			"%-10s %-20s %-6s %5d %8.1f%% %8.1f%% %10.1f %10.2f %15s %12.3f %9.1f\n", kind.c_str(),
			method.c_str(), sensing.c_str(), g.runs, 100.0 * g.reached / n, 100.0 * g.collided / n,
			g.time / k, g.path / k, commonPath.c_str(), g.clearance / n, g.cycle / n);
	}
	out << "(time and path: means over the reached runs; path, all: mean over the worlds every\n"
		   " method of that room kind and sensing reached, how many in brackets; min clr: mean over\n"
		   " all runs of the smallest clearance, negative when it hit)\n";
}

}  // namespace lvf::apps
