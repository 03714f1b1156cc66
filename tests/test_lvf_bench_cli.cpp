// lvf-bench's own options as a user gives them: a seeded room's comparison
// scores the fusion exactly as lvf-fuse scores the same room simulated by
// lvf-simulate (the same frames, the same truth, the same figures), and a bad
// --random-rooms is one line and exit status 2, before any benchmark runs.

#include "CliTestSupport.h"

#include <algorithm>
#include <array>

using namespace lvf::test;

namespace
{
class LvfBenchCli : public CliTest
{
};

/** The first "NAME recall R of N ... phantom rate P of M" after `section`
 * in `text`, for `name`: {R, N, P, M}. */
std::array<double, 4> scoreLine(const std::string& text, const std::string& section, const std::string& name)
{
	const auto from = text.find(section);
	if (from == std::string::npos) return {-1, -1, -1, -1};
	const std::regex line(
		name + R"(\s+recall ([0-9.]+) of (\d+) \(seen by both cameras [0-9.]+\)\s+phantom rate ([0-9.]+) of (\d+))");
	std::smatch m;
	const std::string rest = text.substr(from);
	if (!std::regex_search(rest, m, line)) return {-1, -1, -1, -1};
	return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stod(m[4])};
}
}  // namespace

TEST_F(LvfBenchCli, ASeededRoomIsScoredAsLvfFuseScoresTheSameRoom)
{
	ASSERT_EQ(run(LVF_SIMULATE_BIN, "--random-world 201 -q --outdir sim").status, 0);
	const auto fused = run(LVF_FUSE_BIN, "-i sim/random_201.rawlog --outdir fused --threads 1");
	ASSERT_EQ(fused.status, 0) << fused.err;
	std::smatch m;
	ASSERT_TRUE(std::regex_search(
		fused.out, m,
		std::regex(R"(recall ([0-9.]+) of (\d+) hidden bearings, phantom rate ([0-9.]+) of (\d+) in view)")))
		<< fused.out;
	const double recall = std::stod(m[1]), hidden = std::stod(m[2]), phantom = std::stod(m[3]),
				 inView = std::stod(m[4]);
	ASSERT_GT(hidden, 20);	// a room with something to find

	fs::create_directories(m_dir / "no_scenes");
	const auto bench =
		run(LVF_BENCH_BIN, "--benchmark_filter=NONE --middlebury no_scenes --random-rooms 201");
	ASSERT_EQ(bench.status, 0) << bench.err;
	const std::string section = "Seeded random rooms 201-201";
	const auto fusion = scoreLine(bench.out, section, R"(fusion \(this paper\))");
	EXPECT_NEAR(fusion[0], recall, 0.0005) << bench.out;
	EXPECT_EQ(fusion[1], hidden);
	EXPECT_NEAR(fusion[2], phantom, 0.0005);
	EXPECT_EQ(fusion[3], inView);
	// The dense matchers and the laser are scored over the same hidden
	// bearings (in view depends on each method's ranges, hidden does not).
	for (const std::string name : {"StereoSGBM 3-way", "StereoBM", "laser alone"})
		EXPECT_EQ(scoreLine(bench.out, section, name)[1], hidden) << name;
	EXPECT_EQ(scoreLine(bench.out, section, "laser alone")[0], 0.0);
}

TEST_F(LvfBenchCli, ABadRandomRoomsIsOneLineAndNothingRuns)
{
	for (const std::string args :
		 {"--random-rooms", "--random-rooms 5-3", "--random-rooms x", "--random-rooms=-1", "--random-rooms 3-",
		  "--random-rooms 4294967296", "--random-rooms 1-2-3", "--random-rooms=+4"})
	{
		const auto r = run(LVF_BENCH_BIN, args);
		EXPECT_EQ(r.status, 2) << args;
		EXPECT_EQ(r.out, "") << args;
		EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
		EXPECT_NE(r.err.find("--random-rooms"), std::string::npos) << r.err;
	}
}

TEST_F(LvfBenchCli, OneCaseRunsAloneAndAListRunsNothing)
{
	const auto one = run(LVF_BENCH_BIN, "--no-tables --benchmark_filter=BM_VfhCycle_GridWindow/");
	ASSERT_EQ(one.status, 0) << one.err;
	EXPECT_NE(one.out.find("BM_VfhCycle_GridWindow"), std::string::npos) << one.out;
	EXPECT_NE(one.out.find("VFH+ cycle"), std::string::npos) << one.out;
	EXPECT_EQ(one.out.find("Median time per frame and stage"), std::string::npos) << "no tables";
	const auto list = run(LVF_BENCH_BIN, "--benchmark_list_tests");
	ASSERT_EQ(list.status, 0) << list.err;
	EXPECT_NE(list.out.find("BM_Fusion_BoxRoom"), std::string::npos) << list.out;
	EXPECT_EQ(list.out.find("Median time per frame and stage"), std::string::npos) << "nothing run";
	const auto both = run(LVF_BENCH_BIN, "--no-tables --random-rooms 3");
	EXPECT_EQ(both.status, 2);
	EXPECT_NE(both.err.find("--no-tables: --random-rooms asks for a table"), std::string::npos) << both.err;
}
