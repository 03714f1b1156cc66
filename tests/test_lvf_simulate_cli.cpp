// lvf-simulate as a user runs it: outputs MRPT's own tools can open, and one
// clear line plus exit status 2 for every bad input, with nothing written.

#include "CliTestSupport.h"

using namespace lvf::test;

namespace
{
const std::string kWorlds = std::string(LVF_SHARE_DIR) + "/worlds/";

class LvfSimulateCli : public CliTest
{
   protected:
	RunResult simulate(const std::string& args) const { return run(LVF_SIMULATE_BIN, args); }
};

/** label -> class name, from rawlog-edit --list-timestamps. */
std::map<std::string, std::string> labelClasses(const std::string& list)
{
	std::map<std::string, std::string> classes;
	std::istringstream in(list);
	std::string stamp, label, cls;
	while (in >> stamp >> label >> cls) classes[label] = cls;
	return classes;
}

}  // namespace

TEST_F(LvfSimulateCli, WritesRawlogAndGroundTruthThatMrptToolsOpen)
{
	for (const auto& [format, sfYes] : {std::pair{"sf", "Yes"}, std::pair{"obs", "No"}})
	{
		const std::string outdir = std::string("out_") + format;
		const auto r = simulate(
			"--world " + kWorlds + "box_room.yaml --frames 3 --depth -q --format " +
			format + " --outdir " + outdir);
		ASSERT_EQ(r.status, 0) << r.err;
		EXPECT_EQ(r.out, "");  // -q
		const fs::path dir = m_dir / outdir;
		for (const char* f :
			 {"box_room.rawlog", "box_room_gt_poses.txt", "box_room_truth_scans.csv",
			  "box_room_obstacles.gridmap.gz", "box_room_obstacles.png",
			  "box_room_depth/000002.pfm"})
			EXPECT_TRUE(fs::exists(dir / f)) << f;
		for (const auto& e : fs::directory_iterator(m_dir))
			EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos);

		const auto info = run(LVF_RAWLOG_EDIT, "--info -i " + (dir / "box_room.rawlog").string());
		ASSERT_EQ(info.status, 0) << info.err;
		EXPECT_NE(info.out.find(std::string("Actions/SensoryFrame format       : ") + sfYes),
				  std::string::npos) << info.out;
		const auto counts = labelCounts(info.out);
		EXPECT_EQ(counts.at("LASER"), 3);
		EXPECT_EQ(counts.at("STEREO"), 3);
		if (std::string(format) == "obs")
		{
			EXPECT_EQ(counts.at("ODOMETRY"), 3);
		}

		const auto list = run(LVF_RAWLOG_EDIT,
			"--list-timestamps --text-file-output stamps.txt -i " + (dir / "box_room.rawlog").string());
		ASSERT_EQ(list.status, 0) << list.err;
		const auto classes = labelClasses(slurp(m_dir / "stamps.txt"));
		EXPECT_EQ(classes.at("LASER"), "mrpt::obs::CObservation2DRangeScan");
		EXPECT_EQ(classes.at("STEREO"), "mrpt::obs::CObservationStereoImages");
	}
	// 3 frames + header; truth scans have 181 bearings + frame + timestamp.
	const std::string truth = slurp(m_dir / "out_sf/box_room_truth_scans.csv");
	EXPECT_EQ(std::count(truth.begin(), truth.end(), '\n'), 4);
	const std::string header = truth.substr(0, truth.find('\n'));
	EXPECT_EQ(std::count(header.begin(), header.end(), ','), 182);
}

TEST_F(LvfSimulateCli, RandomWorldsAreNamedBySeedAndReproducible)
{
	for (const char* dir : {"a", "b"}) ASSERT_EQ(simulate(std::string("--random-world 3 -q --outdir ") + dir).status, 0);
	ASSERT_EQ(simulate("--random-world 4 -q --outdir c").status, 0);
	const std::string a = slurp(m_dir / "a/random_3_truth_scans.csv");
	EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 3) << "header + the world's 2 poses";
	EXPECT_EQ(a, slurp(m_dir / "b/random_3_truth_scans.csv")) << "same seed, same world";
	EXPECT_EQ(slurp(m_dir / "a/random_3.rawlog"), slurp(m_dir / "b/random_3.rawlog"));
	EXPECT_NE(a, slurp(m_dir / "c/random_4_truth_scans.csv")) << "another seed, another room";
}

TEST_F(LvfSimulateCli, DumpConfigIsTheShippedSensorsIni)
{
	const auto r = simulate("--dump-config");
	ASSERT_EQ(r.status, 0) << r.err;
	// The shipped file is the dump plus a comment header; keys must agree.
	EXPECT_EQ(keyLines(r.out), keyLines(slurp(std::string(LVF_SHARE_DIR) + "/config/sensors.ini")));
}

TEST_F(LvfSimulateCli, EveryBadInputIsOneLineExitTwoAndNothingWritten)
{
	const auto goodWorld = kWorlds + "two_cubes.yaml";
	const auto badYaml = write("bad.yaml", "name: x\nboxes: [\n");
	const auto unknownKey = write("typo.yaml", "boxes:\n  - {pose: [0,0,0], size: [1,1,1], heigth: 2}\npath: {poses: [[0,0,0]]}\n");
	const auto negative = write("neg.yaml", "boxes:\n  - {pose: [0,0,0], size: [1,-2,1]}\npath: {poses: [[0,0,0]]}\n");
	const auto badKey = write("key.ini", "[SimulatedLaser]\nmax_rnage = 8\n");
	const auto badValue = write("value.ini", "[SimulatedStereoRig]\nfx = fast\n");
	const auto badSection = write("section.ini", "[Lidar]\nmax_range = 8\n");
	const auto badDist = write("dist.ini", "[SimulatedStereoRig]\ndist = 0.1 0.2\n");
	const auto noEquals = write("noeq.ini", "[SimulatedLaser]\n; range\nmax_range 8\n");
	const auto noSection = write("nosec.ini", "max_range = 8\n");
	const auto badHeader = write("header.ini", "[SimulatedLaser\nmax_range = 8\n");
	const auto twice = write("twice.ini", "[SimulatedLaser]\nmax_range = 8\n\nmax_range = 9\n");
	const auto oneRay = write("oneray.ini", "[SimulatedLaser]\naperture_deg = 1\nresolution_deg = 5\n");
	const auto escaping = write("escape.yaml", "name: ../escape\nboxes: []\npath: {poses: [[0,0,0]]}\n");

	const std::vector<std::tuple<std::string, std::string>> cases{
		{"--world /nonexistent.yaml", "/nonexistent.yaml: world file not found"},
		{"--world " + badYaml.string(), "bad.yaml: line 3: malformed YAML"},
		{"--world " + unknownKey.string(), "typo.yaml: line 2: boxes[0].heigth: unknown key 'heigth'"},
		{"--world " + negative.string(), "neg.yaml: line 2: boxes[0].size[1]: -2 is out of range"},
		{"--world " + goodWorld + " --config /nonexistent.ini", "/nonexistent.ini: configuration file not found"},
		{"--world " + goodWorld + " --config " + badKey.string(), "key.ini: [SimulatedLaser] max_rnage: unknown key"},
		{"--world " + goodWorld + " --config " + badValue.string(), "value.ini: [SimulatedStereoRig] fx: 'fast' is not a number"},
		{"--world " + goodWorld + " --config " + badSection.string(), "section.ini: [Lidar]: unknown section"},
		{"--world " + goodWorld + " --config " + badDist.string(), "dist.ini: [SimulatedStereoRig] dist: needs 5 values"},
		{"--world " + goodWorld + " --config " + noEquals.string(), "noeq.ini: line 3: expected 'key = value' or '[section]', got 'max_range 8'"},
		{"--world " + goodWorld + " --config " + noSection.string(), "nosec.ini: line 1: key outside of any [section]"},
		{"--world " + goodWorld + " --config " + badHeader.string(), "header.ini: line 1: malformed section header"},
		{"--world " + goodWorld + " --format bag", "--format: unknown rawlog format 'bag'"},
		{"--world " + goodWorld + " --frames -3", "--frames: must be >= 0"},
		{"--random-world -1", "--random-world: must be >= 0"},
		{"--world " + goodWorld + " --random-world 2", "--random-world: give either --world or --random-world"},
		{"--no-such-flag", "command line"},
		{"--world " + goodWorld + " --config " + twice.string(), "twice.ini: line 4: [SimulatedLaser] max_range: given twice (first on line 2)"},
		{"--world " + goodWorld + " --seed -5", "--seed: must be >= 0"},
		{"--world " + goodWorld + " --config " + oneRay.string(),
			"oneray.ini: [SimulatedLaser] resolution_deg: 5 leaves a single ray in an aperture of 1 deg: must be at most 2"},
		// Names become file names in the output folder: nothing outside it.
		{"--world " + goodWorld + " --name ../escape", "--name: '../escape' must be a plain file name"},
		{"--world " + goodWorld + " --name a/b", "--name: 'a/b' must be a plain file name"},
		{"--world " + escaping.string(), "escape.yaml: line 1: name: '../escape' must be a plain file name"},
	};
	for (const auto& [args, expected] : cases)
	{
		const auto r = simulate(args + " --outdir out");
		EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
		EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
		EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
		EXPECT_EQ(r.err.rfind("lvf-simulate: error: ", 0), 0u) << r.err;
		EXPECT_FALSE(fs::exists(m_dir / "out")) << args;
	}
	// MRPT's tools write `-o OUT.rawlog`; here -o is the output folder.
	const auto r = simulate("--world " + goodWorld + " --outdir sim.rawlog");
	EXPECT_EQ(r.status, 2) << r.err;
	EXPECT_NE(r.err.find("--outdir: 'sim.rawlog' is named like a rawlog"), std::string::npos) << r.err;
	EXPECT_FALSE(fs::exists(m_dir / "sim.rawlog"));
}
