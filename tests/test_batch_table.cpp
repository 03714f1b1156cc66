// lvf-navigate's batch summary (apps/lvf-navigate/BatchTable.h) on
// constructed runs whose means are known: in particular the path over the
// worlds every method reached, the fair comparison of methods' paths.

#include <gtest/gtest.h>

#include <sstream>

#include "BatchTable.h"

using lvf::apps::BatchRow;
using lvf::navigation::Outcome;

namespace
{
BatchRow run(const std::string& world, const std::string& method, const std::string& sensing, bool reached, double path)
{
	BatchRow r{"visible", world, method, sensing, {}};
	r.metrics.outcome = reached ? Outcome::Reached : Outcome::Timeout;
	r.metrics.pathLength = path;
	r.metrics.time = 10;
	return r;
}

/** The table's line for `method` with `sensing`. */
std::string lineOf(const std::string& table, const std::string& method, const std::string& sensing)
{
	std::istringstream in(table);
	for (std::string line; std::getline(in, line);)
		if (line.find(" " + method + " ") != std::string::npos && line.find(" " + sensing + " ") != std::string::npos)
			return line;
	return "";
}
}  // namespace

TEST(BatchTable, PathsAreComparedOverTheWorldsEveryMethodReached)
{
	// A reaches w1-w3 (1, 2, 9 m); B only w1, w2 (1.5, 2.5 m): B's mean
	// over its reached runs (2.0) is shorter than A's (4.0), over the two
	// worlds both reached A is the shorter (1.5 vs 2.0). Fused runs of A
	// alone form their own comparison (every world A reached there).
	const std::vector<BatchRow> rows{
		run("w1", "A", "laser", true, 1.0), run("w1", "B", "laser", true, 1.5),
		run("w2", "A", "laser", true, 2.0), run("w2", "B", "laser", true, 2.5),
		run("w3", "A", "laser", true, 9.0), run("w3", "B", "laser", false, 4.0),
		run("w1", "A", "fused", true, 3.0), run("w2", "A", "fused", false, 1.0)};
	std::ostringstream out;
	lvf::apps::printBatchTable(rows, out);
	const std::string table = out.str();
	// reached %, then path over reached runs, then the common-world path.
	EXPECT_NE(lineOf(table, "A", "laser").find("100.0%"), std::string::npos) << table;
	EXPECT_NE(lineOf(table, "A", "laser").find(" 4.00 "), std::string::npos) << table;
	EXPECT_NE(lineOf(table, "A", "laser").find("1.500 (2)"), std::string::npos) << table;
	EXPECT_NE(lineOf(table, "B", "laser").find("66.7%"), std::string::npos) << table;
	EXPECT_NE(lineOf(table, "B", "laser").find(" 2.00 "), std::string::npos) << table;
	EXPECT_NE(lineOf(table, "B", "laser").find("2.000 (2)"), std::string::npos) << table;
	EXPECT_NE(lineOf(table, "A", "fused").find("3.000 (1)"), std::string::npos) << table;
}

TEST(BatchTable, NoWorldReachedByAllShowsADash)
{
	const std::vector<BatchRow> rows{run("w1", "A", "laser", true, 1.0), run("w1", "B", "laser", false, 1.0)};
	std::ostringstream out;
	lvf::apps::printBatchTable(rows, out);
	const std::string a = lineOf(out.str(), "A", "laser");
	ASSERT_FALSE(a.empty()) << out.str();
	EXPECT_EQ(a.find("(1)"), std::string::npos) << a;
	EXPECT_NE(a.find(" - "), std::string::npos) << a;
}
