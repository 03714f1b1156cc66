#pragma once
// Batch results: one CSV row per run, and a summary table per
// (room kind, method, sensing) group.

#include <lvfusion/navigation/NavigationOutcome.h>

#include <ostream>
#include <string>
#include <vector>

namespace lvf::apps
{
struct BatchRow
{
	std::string roomKind, world, method, sensing;
	lvf::navigation::NavigationMetrics metrics;
};

void writeBatchCsv(const std::vector<BatchRow>& rows, const std::string& path);
/** Per group: runs, reached %, collided %, mean time and path length of the
 * reached runs, mean path over the worlds every method (of that room kind
 * and sensing) reached, mean minimum clearance, mean cycle time. */
void printBatchTable(const std::vector<BatchRow>& rows, std::ostream& out);

}  // namespace lvf::apps
