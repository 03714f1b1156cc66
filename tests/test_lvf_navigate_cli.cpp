// lvf-navigate as a user runs it: bad input is one line and exit status 2
// with nothing written; scenarios that cannot succeed are reported as such
// (exit status 4) with their metrics line; a short laser-only run writes
// every output the issue lists, the rawlog readable by MRPT's tools.

#include "CliTestSupport.h"

using lvf::test::CliTest;
using lvf::test::RunResult;
namespace fs = std::filesystem;

namespace
{
size_t lineCount(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }
}  // namespace

class LvfNavigateCli : public CliTest
{
   protected:
	RunResult navigate(const std::string& args) const { return run(LVF_NAVIGATE_BIN, args); }
	void expectBadInput(const std::string& args, const std::string& mentions) const
	{
		const auto r = navigate(args + " -o out");
		EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
		EXPECT_EQ(lineCount(r.err), 1u) << r.err;
		EXPECT_NE(r.err.find("lvf-navigate: error: "), std::string::npos) << r.err;
		EXPECT_NE(r.err.find(mentions), std::string::npos) << r.err;
		EXPECT_FALSE(fs::exists(m_dir / "out")) << args;
	}
};

TEST_F(LvfNavigateCli, BadInputIsOneLineAndWritesNothing)
{
	expectBadInput("--method CHolonomicNope", "CHolonomicND");	// lists the registered ones
	expectBadInput("--method CPose2D", "not a registered holonomic method");
	expectBadInput("--sensing sonar", "--sensing");
	expectBadInput("--world missing.yaml", "missing.yaml");
	expectBadInput("--start 1,2", "--start");
	expectBadInput("--target 1,x", "'x' is not a number");
	expectBadInput("--batch 0", "--batch");
	expectBadInput("--batch 2 --room-kind attic", "--room-kind");
	const auto bad = write("bad.ini", "[NavigationLoop]\ncontrol_period = 0.1\nno_such_key = 1\n");
	expectBadInput("--config '" + bad.string() + "'", "no_such_key");
	const auto noTarget = write("nt.yaml", "name: nt\npath: {poses: [[0, 0, 0]]}\nboxes: []\n");
	expectBadInput("--world '" + noTarget.string() + "'", "target");
}

TEST_F(LvfNavigateCli, ScenariosThatCannotRunAreReported)
{
	// The box room: floor_a at (2.2, 2.6), float_a (0.6 m up) at (3.6, 2.4).
	const struct
	{
		std::string args, outcome;
	} cases[] = {
		{"--start 2.2,2.6,0", "outcome=start-in-collision"},
		{"--target 3.6,2.4", "outcome=target-in-obstacle"},
		{"--start nan,1,90", "outcome=invalid-pose"},
	};
	for (const auto& c : cases)
	{
		const auto r = navigate(c.args + " --sensing laser -q -o out");
		EXPECT_EQ(r.status, 4) << c.args << "\n" << r.out << r.err;
		EXPECT_NE(r.out.find(c.outcome), std::string::npos) << r.out;
		EXPECT_NE(r.out.find("reached=0"), std::string::npos) << r.out;
		EXPECT_TRUE(fs::exists(m_dir / "out" / "box_room_metrics.txt"));
	}
}

TEST_F(LvfNavigateCli, LaserOnlyBoxRoomRunWritesEveryOutput)
{
	// The laser cannot see float_a: the run ends in a collision (exit 3).
	const auto r = navigate("--sensing laser --method CHolonomicND --timeout 20 -o out");
	EXPECT_EQ(r.status, 3) << r.out << r.err;
	EXPECT_NE(r.out.find("outcome=collision"), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("float_"), std::string::npos) << r.out;
	const auto out = m_dir / "out";
	for (const char* f : {"box_room_trajectory.png", "box_room_run.rawlog", "box_room_metrics.txt"})
		EXPECT_GT(fs::file_size(out / f), 0u) << f;
	bool navlog = false;
	for (const auto& e : fs::directory_iterator(out / "box_room_navlog"))
		navlog |= e.path().extension() == ".reactivenavlog" && fs::file_size(e.path()) > 0;
	EXPECT_TRUE(navlog);
	// The rawlog: one laser scan and one FUSED scan per sensing update.
	const auto info = run(LVF_RAWLOG_EDIT, "--info -i '" + (out / "box_room_run.rawlog").string() + "'");
	const auto counts = lvf::test::labelCounts(info.out);
	ASSERT_EQ(counts.count("FUSED"), 1u) << info.out;
	EXPECT_GT(counts.at("FUSED"), 5);
	EXPECT_EQ(counts.size(), 2u) << info.out;  // no stereo in a laser-only run
}
