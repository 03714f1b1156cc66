// lvf-fuse as a user runs it: outputs MRPT's tools open; a bad file or option
// is one line, exit status 2 and nothing written; a bad frame is one warning
// line and the rest of the log is still fused.

#include "CliTestSupport.h"
#include "TestWorlds.h"

#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include <functional>
#include <sstream>

using namespace lvf::test;
using lvf::simulation::CStereoLaserSimulator;

namespace
{
class LvfFuseCli : public CliTest
{
   protected:
	RunResult fuse(const std::string& args) const { return run(LVF_FUSE_BIN, args); }

	/** Observations a frame also records, besides its scan and stereo pair. */
	using MoreSensors = std::function<void(const CStereoLaserSimulator::Frame&, std::vector<mrpt::obs::CObservation::Ptr>&)>;

	/** A rawlog of the two-cube scene, `frames` poses along x, each frame
	 * passed through `spoil(k, frame)` first (and `more` adding to it). */
	template <typename Spoil>
	fs::path writeLog(const std::string& name, size_t frames, Spoil&& spoil, const MoreSensors& more = {}) const
	{
		auto world = lvf::simulation::loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/two_cubes.yaml");
		world.path.clear();
		for (size_t k = 0; k < frames; k++) world.path.emplace_back(0.05 * double(k), 0, 0);
		CStereoLaserSimulator sim(world, CStereoLaserSimulator::TOptions());
		const fs::path path = m_dir / name;
		lvf::common::RawlogWriter out(path.string(), lvf::common::RawlogFormat::Observations);
		for (size_t k = 0; k < frames; k++)
		{
			auto f = sim.simulateNextFrame(false);
			spoil(k, f);
			std::vector<mrpt::obs::CObservation::Ptr> observations{f.scan, f.stereo};
			if (more) more(f, observations);
			out.append({f.timestamp, f.odometry, observations});
		}
		return path;
	}
};

size_t countLines(const std::string& s) { return static_cast<size_t>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST_F(LvfFuseCli, FusesTheSampleIntoFilesMrptToolsOpen)
{
	const auto r = fuse("--input " + std::string(LVF_SAMPLES_DIR) + "/two_cubes.rawlog --outdir out");
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "");
	EXPECT_NE(r.out.find("recall"), std::string::npos) << "truth scans beside the sample are used";
	EXPECT_NE(r.out.find("whose obstacle both cameras see (two_cubes_seen_truth_scans.csv)"), std::string::npos)
		<< "and the seen truth beside them\n" << r.out;
	for (const char* f : {"two_cubes_fused.rawlog", "two_cubes_laser.gridmap.gz", "two_cubes_fused.gridmap.gz",
						  "two_cubes_grids.png", "two_cubes_frames.csv"})
		EXPECT_TRUE(fs::exists(m_dir / "out" / f)) << f;
	// The grids' picture: laser only | laser + vision, the same area each,
	// under a 24 px line of labels; the floating cube the laser misses is
	// occupied on the right where the left is free.
	const cv::Mat grids = cv::imread((m_dir / "out" / "two_cubes_grids.png").string(), cv::IMREAD_GRAYSCALE);
	ASSERT_FALSE(grids.empty());
	const int panel = (grids.cols - 10) / 2;  // a 10 px gap between
	const cv::Rect area(0, 24, panel, grids.rows - 24);
	const cv::Mat laserPanel = grids(area), fusedPanel = grids(area + cv::Point(panel + 10, 0));
	EXPECT_GT(cv::countNonZero((fusedPanel < 60) & (laserPanel > 150)), 20);
	EXPECT_GE(std::max(area.height, area.width), 300) << "enlarged to be read";
	const auto info = run(LVF_RAWLOG_EDIT, "--info -i out/two_cubes_fused.rawlog");
	ASSERT_EQ(info.status, 0) << info.err;
	const auto counts = labelCounts(info.out);
	for (const char* label : {"LASER", "STEREO", "FUSED", "EVAL"}) EXPECT_EQ(counts.at(label), 1) << label;
	// The fused scans alone, for MRPT's tools that take every scan of a log
	// (README: icp-slam), as rawlog-edit keeps them by label.
	const auto kept = run(LVF_RAWLOG_EDIT, "--keep-label FUSED -i out/two_cubes_fused.rawlog -o fused_only.rawlog");
	ASSERT_EQ(kept.status, 0) << kept.err;
	EXPECT_EQ(labelCounts(run(LVF_RAWLOG_EDIT, "--info -i fused_only.rawlog").out),
		(std::map<std::string, int>{{"FUSED", 1}}));
	// Header + one frame, with the truth columns filled in.
	const std::string csv = slurp(m_dir / "out/two_cubes_frames.csv");
	EXPECT_EQ(countLines(csv), 2u);
	EXPECT_EQ(csv.find(",,"), std::string::npos) << csv;
	// --verbose: each frame's figures as it is fused, the CSV's own.
	const auto verbose = fuse("--input " + std::string(LVF_SAMPLES_DIR) + "/two_cubes.rawlog --outdir v --verbose");
	ASSERT_EQ(verbose.status, 0) << verbose.err;
	const std::string shortened = readCsv(m_dir / "out/two_cubes_frames.csv").at(0).at("shortened_bearings");
	const std::string line = "lvf-fuse: " + std::string(LVF_SAMPLES_DIR) + "/two_cubes.rawlog: frame 0: ";
	const auto at = verbose.out.find(line);
	ASSERT_NE(at, std::string::npos) << verbose.out;
	EXPECT_NE(verbose.out.find("; " + shortened + " of 181 bearings nearer than the laser", at),
		std::string::npos)
		<< verbose.out;
	EXPECT_EQ(r.out.find(": frame 0: "), std::string::npos) << r.out;
}

TEST_F(LvfFuseCli, TheBearingsFileAddsUpToEachFramesFigures)
{
	// The summary and the frames CSV count the in-view bearings up to z_max
	// only (the "over in-view bearings up to Zmax"); the bearings
	// CSV's counted_* columns say which, so that its rows add up to them.
	const auto r = fuse("--input " + std::string(LVF_SAMPLES_DIR) + "/box_room.rawlog --outdir out -q");
	ASSERT_EQ(r.status, 0) << r.err;
	const auto frames = readCsv(m_dir / "out/box_room_frames.csv");
	std::map<std::string, size_t> counted, hidden, recalled;
	size_t inViewBeyond = 0;
	for (const auto& b : readCsv(m_dir / "out/box_room_bearings.csv"))
	{
		counted[b.at("frame")] += b.at("counted_in_view") == "1";
		hidden[b.at("frame")] += b.at("counted_hidden") == "1";
		recalled[b.at("frame")] += b.at("recalled") == "1";
		inViewBeyond += b.at("in_view") == "1" && b.at("counted_in_view") == "0";
		if (b.at("counted_hidden") == "1")
		{
			EXPECT_EQ(b.at("hidden"), "1");
		}
	}
	ASSERT_EQ(frames.size(), 8u);
	for (const auto& f : frames)
	{
		const std::string k = f.at("frame");
		EXPECT_EQ(std::to_string(counted[k]), f.at("in_view")) << "frame " << k;
		EXPECT_EQ(std::to_string(hidden[k]), f.at("hidden")) << "frame " << k;
		if (hidden[k] > 0)
		{
			EXPECT_NEAR(double(recalled[k]) / double(hidden[k]), std::stod(f.at("recall")), 1e-4) << "frame " << k;
		}
	}
	EXPECT_GT(inViewBeyond, 0u) << "the box room has in-view bearings beyond z_max: the columns differ there";
}

TEST_F(LvfFuseCli, EvaluationPicturesCanBeThinnedOut)
{
	// A long log's output need not carry a picture per frame.
	const std::string sample = "--input " + std::string(LVF_SAMPLES_DIR) + "/box_room.rawlog";
	for (const auto& [every, pictures] : {std::pair{"1", 8}, std::pair{"3", 3}, std::pair{"0", 0}})
	{
		const std::string dir = std::string("every") + every;
		const auto r = fuse(sample + " --eval-every " + every + " --outdir " + dir);
		ASSERT_EQ(r.status, 0) << r.err;
		const auto counts = labelCounts(run(LVF_RAWLOG_EDIT, "--info -i " + dir + "/box_room_fused.rawlog").out);
		EXPECT_EQ(counts.at("FUSED"), 8) << every;
		EXPECT_EQ(counts.count("EVAL") ? counts.at("EVAL") : 0, pictures) << every;
	}
}

// A log fused again (another configuration, lvf-navigate's run): this run's
// FUSED scans and EVAL pictures replace the earlier fusion's, one of each a
// frame, in either rawlog layout, and the summary says so.
TEST_F(LvfFuseCli, ALogFusedAgainHoldsOnlyThisRunsResults)
{
	const std::string sample = std::string(LVF_SAMPLES_DIR) + "/box_room.rawlog";
	ASSERT_EQ(fuse("-q --input " + sample + " --outdir first").status, 0);
	// The same frames in the observations layout.
	ASSERT_EQ(run(LVF_SIMULATE_BIN, "-q --format obs --outdir obs").status, 0);
	ASSERT_EQ(fuse("-q --input obs/box_room.rawlog --outdir obs").status, 0);
	for (const std::string again : {"first/box_room_fused.rawlog", "obs/box_room_fused.rawlog"})
	{
		const auto r = fuse("--input " + again + " --outdir second --output second/again.rawlog");
		ASSERT_EQ(r.status, 0) << r.err;
		EXPECT_NE(r.out.find("16 observations of an earlier fusion in the input (FUSED scans, EVAL pictures) "
							 "left out: the output holds this run's"), std::string::npos) << r.out;
		const auto counts = labelCounts(run(LVF_RAWLOG_EDIT, "--info -i second/again.rawlog").out);
		for (const char* label : {"LASER", "STEREO", "FUSED", "EVAL"}) EXPECT_EQ(counts.at(label), 8) << again << " " << label;
	}
}

TEST_F(LvfFuseCli, ThePointsFileHoldsEveryVisualPointEachBearingWasSetFrom)
{
	// --points: every visual point of every frame. They are the frames
	// CSV's counts, lie in the robot's height band, and each visual range of
	// the bearings CSV that was measured (not a closed gap) comes from the
	// points within neighbour_bins (2) + half a bin of its bearing: a
	// point's range, or on a standing surface (standing_median_shift) one
	// between two of their ranges at most cluster_tolerance (0.15 m) apart.
	const std::string sample = "--input " + std::string(LVF_SAMPLES_DIR) + "/box_room.rawlog";
	const auto r = fuse(sample + " --points --eval-every 0 --outdir out");
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(r.out.find("box_room_{frames,bearings,points}.csv"), std::string::npos) << r.out;
	const auto points = readCsv(m_dir / "out/box_room_points.csv");
	const auto frames = readCsv(m_dir / "out/box_room_frames.csv");
	ASSERT_EQ(frames.size(), 8u);
	std::map<std::string, std::map<std::string, size_t>> perFrame;	// frame -> source -> count
	for (const auto& p : points)
	{
		perFrame[p.at("frame")][p.at("source")]++;
		EXPECT_GE(std::stod(p.at("z_m")), 0.05) << p.at("frame");
		EXPECT_LE(std::stod(p.at("z_m")), 1.2) << p.at("frame");
	}
	for (const auto& f : frames)
	{
		auto& counts = perFrame[f.at("frame")];
		EXPECT_EQ(counts["search"] + counts["grown"], std::stoul(f.at("visual_points"))) << f.at("frame");
		EXPECT_EQ(counts["grown"], std::stoul(f.at("grown_points"))) << f.at("frame");
		EXPECT_EQ(counts["remembered"], std::stoul(f.at("remembered_points"))) << f.at("frame");
	}
	size_t explained = 0;
	for (const auto& b : readCsv(m_dir / "out/box_room_bearings.csv"))
	{
		if (b.at("visual_m").empty() || b.at("bridged") == "1") continue;
		const double range = std::stod(b.at("visual_m")), bearing = std::stod(b.at("bearing_deg"));
		std::vector<double> around;	 // the ranges of the points near the bearing
		for (const auto& p : points)
			if (p.at("frame") == b.at("frame") && std::abs(std::stod(p.at("bearing_deg")) - bearing) <= 2.5)
				around.push_back(std::stod(p.at("range_m")));
		const double rounding = 0.0015;	 // the CSVs' millimetres
		const bool found = std::any_of(around.begin(), around.end(), [&](double nearer) {
			return nearer <= range + rounding && std::any_of(around.begin(), around.end(), [&](double farther) {
				return farther >= range - rounding && farther - nearer <= 0.15 + rounding;
			});
		});
		EXPECT_TRUE(found) << "frame " << b.at("frame") << ", " << bearing << " deg, " << range << " m";
		explained += found;
	}
	EXPECT_GT(explained, 100u);
	// Without --points, no such file.
	ASSERT_EQ(fuse(sample + " --eval-every 0 --outdir plain").status, 0);
	EXPECT_FALSE(fs::exists(m_dir / "plain/box_room_points.csv"));
}

TEST_F(LvfFuseCli, DumpConfigIsTheShippedFusionIni)
{
	const auto r = fuse("--dump-config");
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(keyLines(r.out), keyLines(slurp(std::string(LVF_SHARE_DIR) + "/config/fusion.ini")));
}

TEST_F(LvfFuseCli, EveryBadFileOrOptionIsOneLineExitTwoAndNothingWritten)
{
	const auto notRawlog = write("notes.rawlog", "this is not a rawlog\n");
	const auto laserOnly = writeLog("laser_only.rawlog", 2, [](size_t, CStereoLaserSimulator::Frame& f) {
		f.stereo->timestamp = mrpt::Clock::fromDouble(mrpt::Clock::toDouble(f.stereo->timestamp) + 5.0);
	});
	const auto badKey = write("key.ini", "[FocusedEpipolarSearch]\nz_mx = 4\n");
	const auto misplacedKey = write("place.ini", "[CLaserStereoFusion]\nz_max = 4\n");
	const auto badValue = write("value.ini", "[ModelEvaluator]\nwindow_size = 8\n");
	const std::string sample = std::string(LVF_SAMPLES_DIR) + "/two_cubes.rawlog";
	const auto noTruth = write("hello.csv", "hello world\n");
	// A log of 2D scans only, as many of MRPT's sample logs are.
	const auto scansOnly = m_dir / "scans_only.rawlog";
	{
		auto world = lvf::simulation::loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/two_cubes.yaml");
		CStereoLaserSimulator sim(world, CStereoLaserSimulator::TOptions());
		const auto f = sim.simulateNextFrame(false);
		lvf::common::RawlogWriter out(scansOnly.string(), lvf::common::RawlogFormat::Observations);
		out.append({f.timestamp, f.odometry, {f.scan}});
	}
	const auto otherTruth = write("other_truth_scans.csv", "frame,timestamp,b0.00\n0,12345.0,1.5\n");
	fs::create_directories(m_dir / "mydata");
	const auto precious = write("mydata/precious.txt", "the user's\n");
	const auto input = m_dir / "input.rawlog";
	fs::copy_file(sample, input);
	const std::vector<std::pair<std::string, std::string>> cases{
		{"--input /nonexistent.rawlog", "/nonexistent.rawlog: input rawlog not found"},
		{"--input " + notRawlog.string(), "notes.rawlog: record 0: not an MRPT object: corrupt, truncated or not a rawlog"},
		{"--input " + laserOnly.string(), "laser_only.rawlog: no laser scan has a stereo pair within 0.050 s (2 scans, 2 stereo pairs)"},
		{"--input " + sample + " --config " + badKey.string(), "key.ini: [FocusedEpipolarSearch] z_mx: unknown key (did you mean 'z_max'?)"},
		{"--input " + sample + " --config " + misplacedKey.string(), "place.ini: [CLaserStereoFusion] z_max: unknown key (it belongs in [FocusedEpipolarSearch])"},
		{"--input " + sample + " --config " + badValue.string(), "value.ini: [ModelEvaluator] window_size: must be odd"},
		{"--input " + sample + " --max-time-diff -1", "--max-time-diff: must be >= 0"},
		{"--input " + sample + " --threads -2", "--threads: must be >= 0"},
		{"--input " + sample + " --eval-every -1", "--eval-every: must be >= 0"},
		{"--input " + sample + " --output out/", "--output: names a folder, not a file"},
		{"--input " + sample + " --grid-resolution 1e-9", "--grid-resolution: must be in [0.005, 5]"},
		{"--input .", ".: input rawlog is a folder, not a file"},
		{"--input " + sample + " --config .", ".: configuration file is a folder, not a file"},
		{"--input " + sample + " --truth .", ".: truth scan file is a folder, not a file"},
		{"--input " + sample + " --truth /nonexistent.csv", "/nonexistent.csv: truth scan file not found"},
		{"--input " + sample + " --truth " + noTruth.string(), "hello.csv: holds no truth scans"},
		{"--input " + sample + " --truth " + otherTruth.string(), "other_truth_scans.csv: a truth scan (its time stamp and bearings) for 0 of the"},
		{"--input " + sample + " --output mydata", "--output: names a folder, not a file (e.g. mydata/out.rawlog)"},
		{"--input " + input.string() + " --output " + input.string(), "--output: is the input rawlog"},
		{"--input " + sample + " -q -v", "--verbose: contradicts --quiet"},
		{"--input " + scansOnly.string(), "scans_only.rawlog: holds no stereo pairs (CObservationStereoImages) to fuse its 1 2D scan with"},
	};
	for (const auto& [args, expected] : cases)
	{
		const auto r = fuse(args + " --outdir out");
		EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
		EXPECT_EQ(countLines(r.err), 1u) << args << "\n" << r.err;
		EXPECT_EQ(r.err.rfind("lvf-fuse: error: ", 0), 0u) << r.err;
		EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
		EXPECT_FALSE(fs::exists(m_dir / "out")) << args;
	}
	EXPECT_EQ(slurp(precious), "the user's\n");
	EXPECT_EQ(slurp(input), slurp(sample));
	// MRPT's tools write `-o OUT.rawlog`; lvf-fuse's -o is the output folder.
	const auto r = fuse("--input " + sample + " -o fused.rawlog");
	EXPECT_EQ(r.status, 2) << r.err;
	EXPECT_NE(r.err.find("--outdir: 'fused.rawlog' is named like a rawlog"), std::string::npos) << r.err;
	EXPECT_FALSE(fs::exists(m_dir / "fused.rawlog"));
}

TEST_F(LvfFuseCli, AnOutputPlaceThatCannotBeWrittenIsOneLineBeforeAnyWork)
{
	const std::string sample = "--input " + std::string(LVF_SAMPLES_DIR) + "/two_cubes.rawlog";
	write("taken", "a file where a folder should go\n");
	const std::vector<std::pair<std::string, std::string>> cases{
		{"--outdir taken", "taken: exists and is not a folder"},
		{"--outdir taken/out", "taken/out: cannot write the outputs here: Not a directory"},
		{"--outdir out --output taken/fused.rawlog", "taken: exists and is not a folder"},
		{"--outdir /proc/lvf-out", "/proc/lvf-out: cannot write the outputs here"},
	};
	for (const auto& [args, expected] : cases)
	{
		const auto r = fuse(sample + " " + args);
		EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
		EXPECT_EQ(countLines(r.err), 1u) << args << "\n" << r.err;
		EXPECT_NE(r.err.find("lvf-fuse: error: " + expected), std::string::npos) << args << "\n" << r.err;
		EXPECT_EQ(slurp(m_dir / "taken"), "a file where a folder should go\n");
		EXPECT_FALSE(fs::exists(m_dir / "out")) << args;
		for (const auto& entry : fs::directory_iterator(m_dir))	 // no staging folder left behind
			EXPECT_EQ(entry.path().filename().string().find("partial"), std::string::npos) << entry.path();
	}
}

TEST_F(LvfFuseCli, AnOutputRawlogNamedByItselfGoesWhereItIsNamed)
{
	const std::string sample = "--input " + std::string(LVF_SAMPLES_DIR) + "/two_cubes.rawlog --eval-every 0";
	const auto byDefault = fuse(sample + " --outdir out");
	const auto bare = fuse(sample + " --outdir grids --output fused.rawlog");  // no folder: the current one
	const auto nested = fuse(sample + " --outdir grids --output runs/today/fused.rawlog");
	for (const auto* r : {&byDefault, &bare, &nested}) ASSERT_EQ(r->status, 0) << r->err;
	const auto expected = slurp(m_dir / "out" / "two_cubes_fused.rawlog");
	EXPECT_EQ(slurp(m_dir / "fused.rawlog"), expected);
	EXPECT_EQ(slurp(m_dir / "runs" / "today" / "fused.rawlog"), expected);
	EXPECT_FALSE(fs::exists(m_dir / "grids" / "two_cubes_fused.rawlog"));
	for (const auto& entry : fs::directory_iterator(m_dir))	// no staging folder left behind
		EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
}

TEST_F(LvfFuseCli, TheSameOutputsOnOneThreadAsOnSeveral)
{
	const std::string sample = "--input " + std::string(LVF_SAMPLES_DIR) + "/box_room.rawlog";
	const auto one = fuse(sample + " --threads 1 --outdir one");
	const auto two = fuse(sample + " --threads 2 --outdir two");
	ASSERT_EQ(one.status, 0) << one.err;
	ASSERT_EQ(two.status, 0) << two.err;
	EXPECT_EQ(two.err, "");
	EXPECT_NE(one.out.find("(1 thread)"), std::string::npos) << one.out;
	// Where this process may use one CPU only (taskset -c 1, a one-core
	// container) the pool stays at one thread and the summary says why.
	const bool twoCpus = cv::getNumberOfCPUs() >= 2;
	const std::string twoThreads = twoCpus ? "(2 threads)" : "(1 thread of 2 asked: 1 CPU available)";
	EXPECT_NE(two.out.find(twoThreads), std::string::npos) << two.out;
	EXPECT_EQ(slurp(m_dir / "one/box_room_bearings.csv"), slurp(m_dir / "two/box_room_bearings.csv"));
	EXPECT_EQ(slurp(m_dir / "one/box_room_fused.rawlog"), slurp(m_dir / "two/box_room_fused.rawlog"));
}

TEST_F(LvfFuseCli, EachBadFrameIsOneWarningAndTheRestIsFused)
{
	// Frame k is spoiled in way k; frame 0 and the last one are good.
	const auto log = writeLog("spoilt.rawlog", 15, [](size_t k, CStereoLaserSimulator::Frame& f) {
		auto& s = *f.stereo;
		auto& scan = *f.scan;
		switch (k)
		{
			case 1: s.hasImageRight = false, s.imageRight = mrpt::img::CImage(); break;
			case 2: s.imageLeft = mrpt::img::CImage(320, 240, mrpt::img::CH_GRAY); break;
			case 3: s.leftCamera.fx(0); break;
			case 4:
				scan.setScanRange(10, std::numeric_limits<float>::quiet_NaN());
				scan.setScanRange(11, std::numeric_limits<float>::infinity());
				scan.setScanRange(12, -1.f);
				break;
			case 5: scan.resizeScan(0); break;
			case 6:
				for (size_t i = 0; i < scan.getScanSize(); i++) scan.setScanRangeValidity(i, false);
				break;
			case 8:	 // the rig said to look up (no floor in view to judge), and as 7
				s.cameraPose = mrpt::poses::CPose3DQuat(
					mrpt::poses::CPose3D(s.cameraPose) + mrpt::poses::CPose3D(0, 0, 0, 0, 0, mrpt::DEG2RAD(60.0)));
				[[fallthrough]];
			case 7:	 // a calibration so wrong that everything contradicts it
				s.rightCameraPose = mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(0.5, 0, 0, 0, 0, 0));
				break;
			case 9: s.leftCamera.distortion = mrpt::img::DistortionModel::kannala_brandt; break;
			case 10: s.rightCameraPose.m_quat.r(5.0); break;  // MRPT would throw converting it
			case 11: s.cameraPose.x(std::numeric_limits<double>::quiet_NaN()); break;
			// A laser mounted 1e180 m off (fuzz_fusion_frame): MRPT's grid
			// would assert (abort) growing to take it in.
			case 12: scan.sensorPose.y(1e180); break;
			case 13: scan.aperture = 0; break;
			default: break;
		}
	});
	const auto r = fuse("--input " + log.string() + " --outdir out");
	ASSERT_EQ(r.status, 0) << r.err;
	const std::vector<std::string> expected{
		"frame 1: stereo observation has no right image (laser only)",
		"frame 2: left image: 320x240 pixels, but the calibration says 640x480 (laser only)",
		"frame 3: left camera: focal length must be positive and finite",
		"frame 4: scan LASER: 3 rays with NaN, infinite or non-positive range, treated as no return",
		"frame 5: scan LASER: has no rays (laser only)",
		"frame 6: scan LASER has no valid range: no model to check, laser only",
		"frame 7: the images contradict the laser model (",  // "N% of the floor consistent, ..."
		// Not the share of too few floor pixels to judge by (none reads as 100%).
		"frame 8: the images contradict the laser model (too little floor in view to judge, ",
		"frame 9: left camera: fish-eye (kannala_brandt) distortion is not supported: give images rectified by "
		"cv::fisheye, or a plumb_bob calibration (laser only)",
		"frame 10: rightCameraPose: quaternion is not a rotation (squared norm 25): (x y z qr qx qy qz) = (0.12 0 0 5 0 0 0) (laser only)",
		"frame 11: cameraPose: not a finite pose: (x y z qr qx qy qz) = (nan ",
		"frame 12: scan LASER: its pose (odometry and sensor pose) is not finite or lies more than 1000 m outside the "
		"grids: left out of them",
		"frame 13: scan LASER: aperture 0 rad: must be positive and finite (laser only)",
	};
	EXPECT_EQ(countLines(r.err), expected.size()) << r.err;
	for (const auto& e : expected)
		EXPECT_NE(r.err.find("lvf-fuse: warning: " + log.string() + ": " + e), std::string::npos) << e << "\n" << r.err;
	EXPECT_NE(r.err.find("% of the judged pixels inconsistent): stereo calibration suspect, laser only"), std::string::npos);
	EXPECT_NE(r.out.find("15 fused frames"), std::string::npos) << r.out;
	const auto info = run(LVF_RAWLOG_EDIT, "--info -i out/spoilt_fused.rawlog");
	EXPECT_EQ(labelCounts(info.out).at("FUSED"), 15);
}

TEST_F(LvfFuseCli, ScansWithoutAStereoPairInTimeAreCountedAndReported)
{
	// Frames 1 and 3 have their stereo pair 0.5 s late, farther than the
	// pairing tolerance (0.05 s) from any scan: their scans go unfused.
	const auto log = writeLog("late.rawlog", 5, [](size_t k, CStereoLaserSimulator::Frame& f) {
		if (k == 1 || k == 3) f.stereo->timestamp += std::chrono::milliseconds(500);
	});
	const auto r = fuse("--input " + log.string() + " --outdir out");
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(r.out.find("5 scans, 5 stereo pairs, 3 fused frames (2 unpaired scans"), std::string::npos) << r.out;
	EXPECT_EQ(labelCounts(run(LVF_RAWLOG_EDIT, "--info -i out/late_fused.rawlog").out).at("FUSED"), 3);
	// A wider tolerance pairs them again.
	const auto wide = fuse("--input " + log.string() + " --max-time-diff 0.6 --outdir wide");
	ASSERT_EQ(wide.status, 0) << wide.err;
	EXPECT_NE(wide.out.find("5 fused frames (0 unpaired scans"), std::string::npos) << wide.out;
}

TEST_F(LvfFuseCli, WithSeveralLasersOrCamerasTheUserChoosesByLabel)
{
	// Each frame also holds a rear laser's scan and a second camera's pair
	// (copies under other labels): fusing those with the front ones would be
	// wrong without a word, so the user is asked which.
	const auto log = writeLog("four_sensors.rawlog", 3, [](size_t, CStereoLaserSimulator::Frame&) {},
		[](const CStereoLaserSimulator::Frame& f, std::vector<mrpt::obs::CObservation::Ptr>& more) {
			auto rear = std::make_shared<mrpt::obs::CObservation2DRangeScan>(*f.scan);
			rear->sensorLabel = "LASER_REAR";
			auto second = std::make_shared<mrpt::obs::CObservationStereoImages>(*f.stereo);
			second->sensorLabel = "STEREO_2";
			more.push_back(rear);
			more.push_back(second);
		});
	const std::string input = "--input " + log.string();
	const std::vector<std::pair<std::string, std::string>> cases{
		{"", "four_sensors.rawlog: 2D scans from 2 sensors (LASER, LASER_REAR): choose one with --laser-label"},
		{" --laser-label LASER", "four_sensors.rawlog: stereo pairs from 2 sensors (STEREO, STEREO_2): choose one with --stereo-label"},
		{" --laser-label SICK --stereo-label STEREO", "four_sensors.rawlog: no 2D scans labelled 'SICK' (labels: LASER, LASER_REAR)"},
		{" --laser-label LASER --stereo-label BUMBLEBEE", "four_sensors.rawlog: no stereo pairs labelled 'BUMBLEBEE' (labels: STEREO, STEREO_2)"},
	};
	for (const auto& [args, expected] : cases)
	{
		const auto r = fuse(input + args + " --outdir out");
		EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
		EXPECT_EQ(countLines(r.err), 1u) << args << "\n" << r.err;
		EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
		EXPECT_FALSE(fs::exists(m_dir / "out")) << args;
	}
	// Chosen: the front laser with either camera fuses every frame, as the
	// log of the front sensors alone does.
	const auto front = writeLog("front.rawlog", 3, [](size_t, CStereoLaserSimulator::Frame&) {});
	const auto alone = fuse("--input " + front.string() + " --outdir alone");
	ASSERT_EQ(alone.status, 0) << alone.err;
	for (const char* camera : {"STEREO", "STEREO_2"})
	{
		const auto r = fuse(input + " --laser-label LASER --stereo-label " + camera + " --outdir " + camera);
		ASSERT_EQ(r.status, 0) << r.err;
		EXPECT_NE(r.out.find("3 scans, 3 stereo pairs, 3 fused frames (0 unpaired scans"), std::string::npos) << r.out;
		EXPECT_EQ(slurp(m_dir / camera / "four_sensors_bearings.csv"), slurp(m_dir / "alone/front_bearings.csv"));
	}
}

TEST_F(LvfFuseCli, ImagesKeptAsFilesBesideTheLogAreReadAndStayFiles)
{
	// Real logs keep their camera images as files in NAME_Images beside
	// NAME.rawlog (rawlog-grabber, rawlog-edit --externalize); the
	// observations hold only the files' names.
	const auto embedded = writeLog("embedded.rawlog", 4, [](size_t, CStereoLaserSimulator::Frame&) {});
	fs::create_directories(m_dir / "logs");
	const auto externalize = run(LVF_RAWLOG_EDIT, "--externalize -i embedded.rawlog -o logs/stored.rawlog");
	ASSERT_EQ(externalize.status, 0) << externalize.err;
	const fs::path images = m_dir / "logs/stored_Images";
	std::vector<fs::path> files;  // img_STEREO_<time>_{left,right}.png: frame by frame
	for (const auto& e : fs::directory_iterator(images)) files.push_back(e.path());
	std::sort(files.begin(), files.end());
	ASSERT_EQ(files.size(), 8u);

	const auto inMemory = fuse("--input embedded.rawlog --outdir a");
	const auto asFiles = fuse("--input logs/stored.rawlog --outdir b");
	ASSERT_EQ(inMemory.status, 0) << inMemory.err;
	ASSERT_EQ(asFiles.status, 0) << asFiles.err;
	EXPECT_EQ(asFiles.err, "");
	EXPECT_NE(asFiles.out.find("8 images read from logs/stored_Images"), std::string::npos) << asFiles.out;
	EXPECT_EQ(slurp(m_dir / "b/stored_bearings.csv"), slurp(m_dir / "a/embedded_bearings.csv"));

	// The output names them by absolute path, so MRPT's own tools find them
	// from outside its folder (MRPT 2.5.8 would look in "bImages" for
	// names relative to b/): rawlog-edit folds them into a self-contained
	// copy, which fuses to the same bearings.
	fs::create_directories(m_dir / "elsewhere");
	const auto fold = run(LVF_RAWLOG_EDIT, "--de-externalize -i b/stored_fused.rawlog -o elsewhere/self.rawlog");
	ASSERT_EQ(fold.status, 0) << fold.err;
	const auto self = fuse("--input elsewhere/self.rawlog --outdir c");
	ASSERT_EQ(self.status, 0) << self.err;
	EXPECT_EQ(slurp(m_dir / "c/self_bearings.csv"), slurp(m_dir / "a/embedded_bearings.csv"));

	// A missing file and one that is no image: that frame on the laser
	// alone, one warning naming the file; the other frames fused.
	fs::remove(files[3]);					   // frame 1's right image
	std::ofstream(files[4]) << "not a PNG";	   // frame 2's left image
	const auto spoilt = fuse("--input logs/stored.rawlog --outdir d");
	ASSERT_EQ(spoilt.status, 0) << spoilt.err;
	EXPECT_EQ(countLines(spoilt.err), 2u) << spoilt.err;
	for (const auto& [frame, which, file] : {std::tuple{1, "right", files[3]}, std::tuple{2, "left", files[4]}})
		EXPECT_NE(spoilt.err.find("lvf-fuse: warning: logs/stored.rawlog: frame " + std::to_string(frame) + ": " +
					  which + " image: cannot read its file " + file.string() + " (laser only)"),
			std::string::npos)
			<< spoilt.err;
	EXPECT_NE(spoilt.out.find("4 fused frames (0 unpaired scans, 2 bad frames, 2 frames on the laser alone)"),
		std::string::npos)
		<< spoilt.out;
}

TEST_F(LvfFuseCli, ALongLogFusesInTheMemoryOfAFewFrames)
{
	// A real log holds thousands of stereo pairs: lvf-fuse pairs the scans
	// in a first pass that keeps no object, then reads the log again and
	// writes each entry as soon as the frames ending at it are fused.
	const auto shortLog = writeLog("short.rawlog", 4, [](size_t, CStereoLaserSimulator::Frame&) {});
	const auto longLog = writeLog("long.rawlog", 40, [](size_t, CStereoLaserSimulator::Frame&) {});
	const auto shortRun = fuse("--input short.rawlog --outdir short");
	const auto longRun = fuse("--input long.rawlog --outdir long");
	ASSERT_EQ(shortRun.status, 0) << shortRun.err;
	ASSERT_EQ(longRun.status, 0) << longRun.err;
	// Each frame is three entries (odometry, scan, stereo pair): each is
	// written on as soon as it is read (the pair with the frame's results
	// after it), the scan kept for its frame alone until the pair comes.
	EXPECT_NE(longRun.out.find("(1 of 120 rawlog entries held at once)"), std::string::npos) << longRun.out;
	EXPECT_EQ(labelCounts(run(LVF_RAWLOG_EDIT, "--info -i long/long_fused.rawlog").out).at("FUSED"), 40);
	// Holding them all, the 36 frames more would cost about 1.5 MB each
	// (the pair, and the evaluation picture added to the output): 54 MB.
	// What the run may hold besides does not grow with the log: the
	// compressing thread's queue (4 MB, full when the thread lags behind,
	// GzWriterThread.h), the member it gathers and that member compressed
	// (a megabyte and an entry, about 2.5 MB each): up to about 10 MB, the
	// whole of the margin allowed here before. Hence 20 MB.
	auto peakMB = [](const std::string& summary) {
		const auto at = summary.find(" MB of memory at most");
		const auto from = summary.rfind(' ', at - 1) + 1;
		return std::stod(summary.substr(from, at - from));
	};
#if defined(__SANITIZE_ADDRESS__)
	GTEST_SKIP() << "AddressSanitizer holds freed memory back (its quarantine): memory not compared";
#endif
	EXPECT_LT(peakMB(longRun.out) - peakMB(shortRun.out), 20.0) << shortRun.out << longRun.out;
}
