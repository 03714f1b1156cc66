// lvf-navigate as a user runs it: bad input is one line and exit status 2
// with nothing written; scenarios that cannot succeed are reported as such
// (exit status 4) with their metrics line; a short laser-only run writes
// every output the issue lists, the rawlog readable by MRPT's tools, the
// poses adding up to the path it reports.

#include "CliTestSupport.h"
#include "TestWorlds.h"

#include <lvfusion/metrics/PoseTrajectory.h>

#include <csignal>
#include <cstdlib>

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
	expectBadInput("--threads -1", "--threads: must be >= 0");
	expectBadInput("--batch 2 --room-kind attic", "--room-kind");
	expectBadInput("--room-kind visible", "--room-kind: only for random rooms");  // the box room would run
	expectBadInput("-r 3 --room-kind overhangs,visible", "--room-kind: a single run takes one room kind");
	// A list's items are trimmed: the kinds parse, and only their number is wrong.
	expectBadInput("-r 3 --room-kind 'overhangs, visible'", "--room-kind: a single run takes one room kind");
	const auto bad = write("bad.ini", "[NavigationLoop]\ncontrol_period = 0.1\nno_such_key = 1\n");
	expectBadInput("--config '" + bad.string() + "'", "no_such_key");
	// MRPT's navigator reads this section itself: checked before it does.
	const auto badVfh = write("badvfh.ini", "[CHolonomicVFH]\nsafety_fallback = maybe\n");
	expectBadInput("--config '" + badVfh.string() + "'", "badvfh.ini: [CHolonomicVFH] safety_fallback");
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
		// Nothing was sensed: no empty rawlog, no empty navigation log.
		EXPECT_FALSE(fs::exists(m_dir / "out" / "box_room_run.rawlog")) << c.args;
		EXPECT_FALSE(fs::exists(m_dir / "out" / "box_room_navlog")) << c.args;
		fs::remove_all(m_dir / "out");
	}
}

TEST_F(LvfNavigateCli, AnInterruptedRunLeavesNothingBehind)
{
	// Ctrl-C or `kill` in the middle of a run: the process ends by that
	// signal, and neither its hidden staging folder nor its scratch folder
	// (under TMPDIR) stays.
	const fs::path scratch = m_dir / "tmp";
	fs::create_directories(scratch);
	for (const int signal : {SIGINT, SIGTERM})
	{
		const pid_t child = fork();
		ASSERT_GE(child, 0);
		if (child == 0)
		{
			setenv("TMPDIR", scratch.c_str(), 1);
			if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) _exit(127);
			const std::string out = (m_dir / "out").string();
			execl(LVF_NAVIGATE_BIN, LVF_NAVIGATE_BIN, "-q", "--threads", "1", "-o", out.c_str(), static_cast<char*>(nullptr));
			_exit(127);
		}
		// Wait for the run's staging folder (".out.partial-PID" beside "out").
		const fs::path staging = m_dir / (".out.partial-" + std::to_string(child));
		for (int i = 0; i < 600 && !fs::exists(staging / "box_room_navlog"); i++) usleep(50000);
		ASSERT_TRUE(fs::exists(staging)) << "the run never started";
		usleep(300000);	 // well into the run
		kill(child, signal);
		int status = 0;
		ASSERT_EQ(waitpid(child, &status, 0), child);
		EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
		EXPECT_FALSE(fs::exists(staging)) << staging;
		EXPECT_FALSE(fs::exists(m_dir / "out"));
		EXPECT_TRUE(fs::is_empty(scratch)) << (fs::directory_iterator(scratch)->path());
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
	for (const char* f : {"box_room_trajectory.png", "box_room_poses.txt", "box_room_run.rawlog", "box_room_metrics.txt"})
		EXPECT_GT(fs::file_size(out / f), 0u) << f;
	// The poses: one a control step (0.1 s) from the start, whose steps add
	// up to the metrics line's path (a collision ends the path at its step).
	const auto poses = lvf::metrics::readPoseFile((out / "box_room_poses.txt").string());
	ASSERT_GT(poses.size(), 10u);
	double path = 0;
	for (size_t k = 1; k < poses.size(); k++)
	{
		EXPECT_NEAR(poses[k].timestamp - poses[k - 1].timestamp, 0.1, 1e-6);
		path += poses[k].pose.distanceTo(poses[k - 1].pose);
	}
	const size_t at = r.out.find("path=");
	ASSERT_NE(at, std::string::npos) << r.out;
	EXPECT_NEAR(path, std::stod(r.out.substr(at + 5)), 0.005);
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

TEST_F(LvfNavigateCli, DumpConfigIsCompleteAndReadsBack)
{
	const auto r = navigate("--dump-config");
	ASSERT_EQ(r.status, 0) << r.err;
	// Every [NavigationLoop] key of the shipped file, MRPT's navigator
	// sections with keys the shipped file leaves to MRPT's defaults, every
	// registered holonomic method, the PTGs, the simulator and the fusion.
	for (const char* key :
		 {"[NavigationLoop]", "global_guidance", "guidance_lookahead", "unreachable_after", "turn_in_place_above_deg",
		  "[CAbstractPTGBasedReactive]", "speedfilter_tau", "[CHolonomicVFH]", "[CHolonomicFullEval]",
		  "[CHolonomicVFF]", "[CHolonomicND]", "PTG2_Type", "[CStereoLaserSimulator]", "[SimulatedStereoRig]",
		  "[CLaserStereoFusion]", "[FocusedEpipolarSearch]"})
		EXPECT_NE(r.out.find(key), std::string::npos) << key;
	for (const auto& line : lvf::test::keyLines(lvf::test::slurp(std::string(LVF_SHARE_DIR) + "/config/navigate.ini")))
	{
		if (line[0] == '[') continue;
		const std::string key = line.substr(0, line.find_first_of(" =\t"));
		EXPECT_NE(r.out.find("\n" + key + " "), std::string::npos) << key;
	}
	// It reads back as --config, values changed in it are used.
	const auto dump = write("dump.ini", r.out);
	EXPECT_EQ(navigate("--config '" + dump.string() + "' --dump-config").out, r.out);
	std::string edited = r.out;
	const std::string from = "global_guidance              =  true", to = "global_guidance              =  false";
	ASSERT_NE(edited.find(from), std::string::npos);
	edited.replace(edited.find(from), from.size(), to);
	const auto tilt = edited.find("tilt_deg                     =  15.000000");
	ASSERT_NE(tilt, std::string::npos);
	edited.replace(tilt, 41, "tilt_deg                     =  20.000000");
	const auto editedIni = write("edited.ini", edited);
	const auto again = navigate("--config '" + editedIni.string() + "' --dump-config --method CHolonomicVFH").out;
	EXPECT_NE(again.find(to), std::string::npos);
	EXPECT_NE(again.find("tilt_deg                     =  20.000000"), std::string::npos);
	EXPECT_NE(again.find("holonomic_method = CHolonomicVFH"), std::string::npos);
	// A bad key in one of the simulator's sections of it names the file.
	const auto badSim = write("badsim.ini", r.out + "\n[SimulatedLaser]\nno_such_key = 1\n");
	expectBadInput("--config '" + badSim.string() + "'", "badsim.ini: [SimulatedLaser] no_such_key");
	// The shipped MRPT-style navigator file: no [CHolonomicFullEval] section
	// MRPT would accept, which only matters once that method is chosen.
	const auto mrptStyle = navigate("--config '" + std::string(LVF_SHARE_DIR) + "/config/reactive_vfh.ini' --dump-config");
	EXPECT_EQ(mrptStyle.status, 0) << mrptStyle.err;
	EXPECT_NE(mrptStyle.out.find("[CHolonomicVFH]"), std::string::npos);
}

TEST_F(LvfNavigateCli, ANavigatorConfigMrptRefusesIsOneLineNamingTheFile)
{
	// MRPT's navigator checks these itself, by exceptions of its own: each
	// is one line naming the file, status 2, nothing written. The first
	// three fail as MRPT loads the file, the last two only where it builds
	// its PTGs' tables, at the start of a run.
	const std::string shipped = lvf::test::slurp(std::string(LVF_SHARE_DIR) + "/config/navigate.ini");
	const struct
	{
		std::string from, to, mentions;
	} cases[] = {
		{"PTG_COUNT = 3", "PTG_COUNT = three", "nPTGs != 0"},
		{"PTG0_Type = CPTG_DiffDrive_C", "PTG0_Type = CPTG_Nope", "No PTG named `CPTG_Nope`"},
		{"PTG_COUNT = 3", "PTG_COUNT = 4", "'PTG3_Type' not found"},
		{"PTG0_resolution = 0.05", "PTG0_resolution = 0", "m_resolution > 0"},
		{"PTG0_refDistance = 4.0", "PTG0_refDistance = -4", "refDistance > 0"},
	};
	for (const auto& c : cases)
	{
		std::string text = shipped;
		const auto at = text.find(c.from);
		ASSERT_NE(at, std::string::npos) << c.from;
		text.replace(at, c.from.size(), c.to);
		const auto ini = write("nav.ini", text);
		expectBadInput("--config '" + ini.string() + "' --sensing laser",
			"nav.ini: MRPT's reactive navigator refuses it: ");
		expectBadInput("--config '" + ini.string() + "' --sensing laser", c.mentions);
	}
}

TEST_F(LvfNavigateCli, ANavigatorThatFailsWithinItsStepEndsTheRunAtOnce)
{
	// A score formula that does not compile: MRPT finds it only in its
	// navigation step and stops as in an emergency, every step again;
	// replanning cannot mend it, so the run ends there (not at the
	// timeout) with MRPT's reason.
	std::string text = lvf::test::slurp(std::string(LVF_SHARE_DIR) + "/config/navigate.ini");
	const auto formula = text.find("scalar_score_formula = ");
	ASSERT_NE(formula, std::string::npos);
	text.replace(formula, text.find('\n', formula) - formula, "scalar_score_formula = target_distance*(");
	const auto ini = write("formula.ini", text);
	const auto r = navigate("--config '" + ini.string() + "' --sensing laser --timeout 30 -q -o out");
	EXPECT_EQ(r.status, 3) << r.out << r.err;
	EXPECT_NE(r.out.find("outcome=navigator-error"), std::string::npos) << r.out;
	const std::string detail = lvf::test::slurp(m_dir / "out" / "box_room_metrics.txt");
	EXPECT_NE(detail.find("the navigator failed after "), std::string::npos) << detail;
	EXPECT_NE(detail.find("Mismatched brackets"), std::string::npos) << detail;
	EXPECT_EQ(r.out.find("time=30.0s"), std::string::npos) << r.out;
}

TEST_F(LvfNavigateCli, UnreachableTargetIsReportedAsSuch)
{
	// A closed, empty 6 x 6 m room and a target 3 m beyond its east wall:
	// once the robot has seen the walls all round, guidance finds no way
	// (exit status 3: ran, not reached).
	const auto world = write("closed.yaml", lvf::test::roomWorld("") + "target: [8, 0]\n");
	const auto r = navigate("--world '" + world.string() + "' --sensing laser --timeout 60 -q -o out");
	EXPECT_EQ(r.status, 3) << r.out << r.err;
	EXPECT_NE(r.out.find("outcome=unreachable"), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("collisions=0"), std::string::npos) << r.out;
	EXPECT_NE(lvf::test::slurp(m_dir / "out" / "room_metrics.txt").find("the target is unreachable"), std::string::npos);
}
