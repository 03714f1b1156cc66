// The whole pipeline (CLaserStereoFusion: the scan's own line segments as the
// model) on seeded random worlds that are not the shipped samples: floating
// boxes, tables, wall shelves, textureless surfaces. Scored with DESIGN.md's
// metrics against the simulator's truth scans.

#include <gtest/gtest.h>
#include <lvfusion/common/LaserRange.h>
#include <lvfusion/evaluation/ImageNoise.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/RandomWorld.h>

#include "CliTestSupport.h"
#include "TestWorlds.h"

#include <algorithm>
#include <cmath>
#include <functional>

using namespace lvf;

namespace
{
metrics::FusionScore fuseWorld(uint32_t seed, fusion::CLaserStereoFusion::StageTimes& times, size_t& frames,
	const simulation::CStereoLaserSimulator::TOptions& sensors = {}, const fusion::CLaserStereoFusion::TOptions& options = {})
{
	const auto world = simulation::generateRandomWorld(seed);
	simulation::CStereoLaserSimulator sim(world, sensors);
	fusion::CLaserStereoFusion fusion(options);
	metrics::FusionScore score;
	for (size_t k = 0; k < sim.frameCount(); k++)
	{
		const auto f = sim.simulateNextFrame(false);
		const auto r = fusion.process(*f.scan, *f.stereo, "frame " + std::to_string(k), f.odometry);
		EXPECT_FALSE(r.fellBackToLaser) << (r.warnings.empty() ? "" : r.warnings.front());
		const auto inView = metrics::bearingsInView(
			*f.scan, f.truthScan, *f.stereo, fusion.options().band, fusion.options().depth.zMax);
		score.add(metrics::scoreFusedScan(*f.scan, *r.fused, f.truthScan, inView, fusion.options().depth.zMax));
		times.search += r.times.search;
		times.evaluate += r.times.evaluate;
		frames++;
	}
	return score;
}
}  // namespace

TEST(FusionPipeline, SeededWorldsRecallWhatTheLaserMisses)
{
	metrics::FusionScore total;
	fusion::CLaserStereoFusion::StageTimes times;
	size_t frames = 0;
	for (uint32_t seed = 1; seed <= 6; seed++)
	{
		const auto s = fuseWorld(seed, times, frames);
		std::cout << "world " << seed << ": hidden " << s.hidden << ", recall " << s.recall()
				  << ", phantom rate " << s.phantomRate() << " of " << s.inView
				  << ", hidden range error " << s.hiddenRangeErrorMedian() << " m\n";
		total.add(s);
	}
	std::cout << "all " << frames << " frames: hidden " << total.hidden << ", recall " << total.recall()
			  << ", phantom rate " << total.phantomRate() << " of " << total.inView
			  << ", hidden range error " << total.hiddenRangeErrorMedian() << " m; search "
			  << times.search / frames << " ms, evaluation " << times.evaluate / frames << " ms per frame\n";
	RecordProperty("recall", std::to_string(total.recall()));
	RecordProperty("phantom_rate", std::to_string(total.phantomRate()));
	EXPECT_GT(total.hidden, 100u);
	// Issue #3 asks for recall >= 0.90 and phantom rate <= 0.02 here; the
	// pipeline did not reach that at first (recall 0.838, phantom rate 0.033
	// when this was written; seeds 11-16, not used for tuning: 0.909,
	// 0.043). A third of the misses are bearings where no pixel of the
	// image shows the obstacle (the bearing's plane is in view, the
	// obstacle's heights there are not). Thin table tops seen almost edge-on and objects near z_max are
	// missed; at 4-5 m a quarter-pixel of disparity is 0.1 m, the metrics'
	// tolerance; most phantoms are the bearing beside an object (its
	// silhouette matched half a window too wide). These bounds guard the
	// present level against regressions; tighten them as it improves. With
	// the exact model (test_visual_depth) the targets are met. The memory of
	// the first frame's points (VisualPointMemory) took recall from 0.863 to
	// 0.891 with the same phantoms: each room's second frame, 0.2 m on, has
	// lost some of what the first saw out of its view. Closing narrow gaps
	// along an obstacle's edge (NarrowGapBridging.h: a table top's front
	// edge found on most bearings, not all) took it to 0.901 (256 of 284),
	// phantoms unchanged. The shifted windows and the sub-pixel steps, on
	// by default since 2026-12-03, keep matches off the background beside
	// objects: recall 0.912 (259 of 284), phantom rate 0.033 -> 0.019 (11
	// of 577): both of the targets, met here (lvf-fuse on these
	// rooms' rawlogs, with the rawlog's noisy odometry: the same). The range
	// rules of 2026-12-03 (ScanFusion.h: central_share, range_support),
	// chosen for the real images (Middlebury Motorcycle 0.739 -> 0.826),
	// trade a little recall for fewer phantoms here: 0.901 (256 of 284),
	// 0.017 (10 of 577). The search's nearest-first passes (2026-12-04,
	// test_nearest_first_search): 0.905 (257 of 284), 0.017 (10 of 577).
	EXPECT_GE(total.recall(), 0.90);
	EXPECT_LE(total.phantomRate(), 0.02);
	EXPECT_LE(total.hiddenRangeErrorMedian(), 0.05);
}

TEST(FusionPipeline, ObstaclesTheLaserSeesGiveNoVisualObstacles)
{
	// Paper Fig. 3c: the cube on the floor is in the laser's model, so the
	// cameras agree with it and vision adds no obstacle there. Rooms with
	// boxes standing on the floor only (some taller than the robot, some
	// turned) and the default, noisy sensors: every bearing the fused scan
	// puts nearer than both the truth and the laser is a phantom.
	const std::vector<std::string> layouts{
		"  - {pose: [2.2, -0.6, 0], size: [0.5, 0.5, 0.5]}\n"
		"  - {pose: [3.0, 1.0, 0.4], size: [0.6, 0.4, 1.1]}\n",
		"  - {pose: [1.8, 0.0, 0.8], size: [0.4, 0.4, 0.7]}\n"
		"  - {pose: [3.5, -1.5, 0], size: [0.8, 0.5, 1.5]}\n",
		"  - {pose: [2.5, 1.5, -0.3], size: [1.0, 0.3, 0.9]}\n"
		"  - {pose: [2.0, -1.2, 0], size: [0.3, 0.3, 0.4]}\n"
		"  - {pose: [4.0, 0.2, 0], size: [0.5, 0.5, 1.2]}\n"};
	metrics::FusionScore total;
	for (const auto& boxes : layouts)
	{
		const auto world = lvf::test::worldFromText(lvf::test::roomWorld(boxes));
		simulation::CStereoLaserSimulator sim(world, simulation::CStereoLaserSimulator::TOptions());
		const auto f = sim.simulateNextFrame(false);
		fusion::CLaserStereoFusion fusion;
		const auto r = fusion.process(*f.scan, *f.stereo, "frame");
		ASSERT_FALSE(r.fellBackToLaser);
		const auto inView = metrics::bearingsInView(
			*f.scan, f.truthScan, *f.stereo, fusion.options().band, fusion.options().depth.zMax);
		const auto s = metrics::scoreFusedScan(*f.scan, *r.fused, f.truthScan, inView, fusion.options().depth.zMax);
		EXPECT_EQ(s.hidden, 0u) << "the laser sees every obstacle here";
		total.add(s);
	}
	std::cout << "phantom bearings " << total.phantoms << " of " << total.inView << " in view\n";
	// The aim is none. Measured: 1 of 147. The bearing just beside a box's
	// silhouette is where they come from: a window half on the box matches
	// at the box's depth (window-based stereo's "foreground fattening"); 5
	// of 148 until each match's core window had to match better than at the
	// model's disparity.
	EXPECT_LE(total.phantomRate(), 0.02);
}

namespace
{
/** One frame of a run: its score and how many visual points it found and
 * remembered. */
struct FrameOfRun
{
	metrics::FusionScore score;
	size_t found = 0, remembered = 0;
};

/** Every frame of `world`'s path fused in order with odometry, the default
 * noisy sensors, and the visual point memory set to `maxTravel`. */
std::vector<FrameOfRun> fuseRun(const std::string& worldYaml, double maxTravel)
{
	simulation::CStereoLaserSimulator sim(lvf::test::worldFromText(worldYaml), simulation::CStereoLaserSimulator::TOptions());
	fusion::CLaserStereoFusion::TOptions o;
	o.memory.maxTravel = maxTravel;
	fusion::CLaserStereoFusion fusion(o);
	std::vector<FrameOfRun> frames;
	for (size_t k = 0; k < sim.frameCount(); k++)
	{
		const auto f = sim.simulateNextFrame(false);
		const auto r = fusion.process(*f.scan, *f.stereo, "frame", f.odometry);
		const auto inView = metrics::bearingsInView(*f.scan, f.truthScan, *f.stereo, o.band, o.depth.zMax);
		frames.push_back({metrics::scoreFusedScan(*f.scan, *r.fused, f.truthScan, inView, o.depth.zMax),
			r.search.points.size(), r.remembered.size()});
	}
	return frames;
}

/** The world's text with its path's waypoints (or poses) replaced. */
std::string withPath(std::string yaml, const std::string& path, const std::string& replacement)
{
	yaml.replace(yaml.find(path), path.size(), replacement);
	return yaml;
}

/** The last frame's score of a run towards a box 0.2 m tall (under the
 * laser's plane) whose front ends 0.8 m ahead of the robot there. */
metrics::FusionScore lastFrameNearALowBox(double maxTravel)
{
	const auto frames = fuseRun(withPath(lvf::test::roomWorld("  - {pose: [1.6, 0, 0], size: [0.4, 0.6, 0.2]}\n"),
									"[[0, 0, 0]]", "[[0, 0, 0], [0.3, 0, 0], [0.6, 0, 0]]"),
		maxTravel);
	for (size_t k = 0; k < frames.size(); k++)
		std::cout << "max_travel " << maxTravel << ", frame " << k << ": " << frames[k].found << " points found, "
				  << frames[k].remembered << " remembered; recall " << frames[k].score.recall() << " of "
				  << frames[k].score.hidden << " hidden bearings, " << frames[k].score.phantoms << " phantoms\n";
	return frames.back().score;
}
}  // namespace

// Close to a low obstacle only vision finds, its front leaves the bottom of
// the image (the cameras 1 m up, 15 deg down, see the floor from 1.07 m);
// the frames before saw it. The memory keeps it where the view cannot.
TEST(FusionPipeline, RemembersTheFrontOfALowBoxAfterItLeftTheImage)
{
	const auto alone = lastFrameNearALowBox(0), remembered = lastFrameNearALowBox(1.5);
	EXPECT_GT(alone.hidden, 5u);
	EXPECT_LE(alone.recall(), 0.5);
	EXPECT_GE(remembered.recall(), 0.9);
	// The remembered box is carried by odometry, whose reading after 0.6 m
	// errs by about a centimetre sideways: at 0.7 m that is most of a 1 deg
	// bearing, so a side of it may spill into the bearings beside it
	// (simulator seeds 1-12: 0-2 phantom bearings, each one or two bearings
	// off a side of the box).
	EXPECT_LE(remembered.phantoms, 2u);
}

namespace
{
/** All frames' score of a 33-frame tour of the box room (Fig. 7) with two
 * left turns and a slant, the default noisy sensors and odometry. */
metrics::FusionScore boxRoomTour(double maxTravel)
{
	const auto frames = fuseRun(withPath(lvf::test::slurp(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml"),
									"[[3.0, 0.6], [3.0, 2.0]]",
									"[[3.0, 0.6], [3.0, 1.7], [1.4, 1.7], [1.4, 3.5], [2.0, 5.2]]"),
		maxTravel);
	metrics::FusionScore total;
	for (const auto& f : frames) total.add(f.score);
	std::cout << "max_travel " << maxTravel << ", " << frames.size() << " frames: recall " << total.recall()
			  << " of " << total.hidden << " hidden bearings, " << total.phantoms << " phantoms of "
			  << total.inView << " in view\n";
	return total;
}
}  // namespace

// The memory over a longer run, turns and odometry noise included: what it
// adds must be there (measured: recall 0.854 -> 0.952 of 437 hidden
// bearings, 14 phantom bearings of 2650 either way).
TEST(FusionPipeline, ATourOfTheBoxRoomRemembersWithoutNewPhantoms)
{
	const auto alone = boxRoomTour(0), remembered = boxRoomTour(1.5);
	ASSERT_GT(alone.hidden, 300u);
	EXPECT_GE(remembered.recall(), alone.recall() + 0.05);
	EXPECT_GE(remembered.recall(), 0.93);
	EXPECT_LE(remembered.phantoms, alone.phantoms);
}

namespace
{
/** Each visual point of seeded rooms 1-3, with the search's options set by
 * `configure`, against the simulator's depth at its pixel. Every grid row
 * is matched (nearest first off): these tests judge matches, and nearest
 * first leaves a row's matches out by what other rows found (with it, the
 * shifted windows' test below measured 10.4 % -> 9.0 %, 259 of 2492 ->
 * 217 of 2412: fewer points on what was already found, so a larger share
 * at edges). */
struct MatchError
{
	double depth;  //!< |Z - true Z| [m]
	double disparity;  //!< disparity - true disparity [px]
};
std::vector<MatchError> matchErrors(const std::function<void(depth::FocusedEpipolarSearch::TOptions&)>& configure)
{
	fusion::CLaserStereoFusion::TOptions o;
	o.depth.nearestFirstLevels = 0;
	configure(o.depth);
	std::vector<MatchError> errors;
	for (uint32_t seed = 1; seed <= 3; seed++)
	{
		simulation::CStereoLaserSimulator sim(
			simulation::generateRandomWorld(seed), simulation::CStereoLaserSimulator::TOptions());
		fusion::CLaserStereoFusion fusion(o);
		for (size_t k = 0; k < sim.frameCount(); k++)
		{
			const auto f = sim.simulateNextFrame(true);
			const auto r = fusion.process(*f.scan, *f.stereo, "frame");
			EXPECT_FALSE(r.geometry.f <= 0);
			for (const auto& p : r.search.points)
			{
				const double trueDepth = f.leftDepth(int(p.v), int(p.u));
				if (!std::isfinite(trueDepth)) continue;
				errors.push_back({std::abs(r.geometry.fB() / p.disparity - trueDepth),
								  p.disparity - r.geometry.fB() / trueDepth});
			}
		}
	}
	return errors;
}

/** Share of those points more than 0.3 m off. */
double shareOfWrongMatches(const char* what, const std::function<void(depth::FocusedEpipolarSearch::TOptions&)>& configure)
{
	const auto errors = matchErrors(configure);
	const auto wrong = std::count_if(errors.begin(), errors.end(), [](const MatchError& e) { return e.depth > 0.3; });
	std::cout << what << ": " << errors.size() << " matches, " << wrong << " more than 0.3 m off the true depth\n";
	return double(wrong) / double(std::max<size_t>(errors.size(), 1));
}
}  // namespace

// A window centred on the background just beside an object's silhouette
// holds part of the object and matches at the object's depth, so objects
// come out too wide (phantoms on the bearing beside them). Counted against
// the simulator's per-pixel depth: matches more than 0.3 m off.
TEST(FusionPipeline, CoreWindowKeepsMatchesOffTheBackgroundBesideObjects)
{
	// The core window must match too, and better than at the model's
	// disparity (the background's), and there it does not. Measured (both
	// without the shifted windows, which came later): 14.0% without (667 of
	// 4756), 8.3% with (356 of 4265).
	const double without = shareOfWrongMatches("no core window, no shifted windows", [](auto& d) {
		d.coreWindow = 0;
		d.shiftedWindows = false;
	});
	const double with = shareOfWrongMatches("core window, no shifted windows", [](auto& d) { d.shiftedWindows = false; });
	EXPECT_LT(with, 0.75 * without);
}

TEST(FusionPipeline, ShiftedWindowsKeepMatchesOffTheBackgroundBesideObjects)
{
	// The core window still reaches a few pixels onto the object; a window
	// shifted sideways until the pixel is on its edge does not, and on the
	// background's side the model explains it. Measured: 8.3% (356 of 4265)
	// -> 6.9% (286 of 4140); of the 125 matches it takes away, 70 are such.
	const double without = shareOfWrongMatches("core window, no shifted windows", [](auto& d) { d.shiftedWindows = false; });
	const double with = shareOfWrongMatches("core window and shifted windows", [](auto& d) { d.shiftedWindows = true; });
	EXPECT_LT(with, 0.85 * without);
}

// The parabola through three NCC scores weighs the whole window alike, so a
// window over two surfaces (an edge, a table top's front, the floor below a
// box) puts the match between their disparities. Lucas-Kanade steps on a
// window weighted round its centre let the centre pixel's surface decide.
// Measured against the simulator's depth at each point's pixel, over the
// points within a pixel of it (rooms 1-3): median |error| 0.075 -> 0.063 px,
// 90th percentile 0.299 -> 0.242 px.
TEST(FusionPipeline, SubpixelRefinementPutsMatchesAtTheirPixelsDepth)
{
	auto summary = [](const char* what, int iterations) {
		const auto errors = matchErrors([&](auto& d) { d.subpixelIterations = iterations; });
		std::vector<double> within;
		for (const auto& e : errors)
			if (std::abs(e.disparity) < 1) within.push_back(std::abs(e.disparity));
		std::sort(within.begin(), within.end());
		const double median = within.empty() ? 1.0 : within[within.size() / 2];
		const double p90 = within.empty() ? 1.0 : within[within.size() * 9 / 10];
		std::cout << what << ": " << errors.size() << " points, " << within.size()
				  << " within 1 px of the true disparity: median |error| " << median << " px, 90th percentile "
				  << p90 << " px\n";
		return std::make_pair(median, p90);
	};
	const auto parabola = summary("parabola alone", 0);
	const auto refined = summary("parabola + 2 Lucas-Kanade steps", 2);
	EXPECT_LT(refined.first, 0.9 * parabola.first);
	EXPECT_LT(refined.second, 0.95 * parabola.second);
}

TEST(FusionPipeline, WarningsAndEachFramesFiguresGoThroughMrptsLogger)
{
	// An MRPT program embedding the class sees its warnings as it sees
	// MRPT's own (COutputLogger, WARN), and each frame's figures at DEBUG.
	auto world = simulation::loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/two_cubes.yaml");
	world.path = {{0, 0, 0}, {0.05, 0, 0}};
	simulation::CStereoLaserSimulator sim(world, simulation::CStereoLaserSimulator::TOptions());
	fusion::CLaserStereoFusion fusion;
	std::vector<std::pair<mrpt::system::VerbosityLevel, std::string>> logged;
	fusion.logging_enable_console_output = false;
	fusion.logRegisterCallback([&](std::string_view msg, mrpt::system::VerbosityLevel level, auto, auto) {
		logged.emplace_back(level, std::string(msg));
	});

	auto first = sim.simulateNextFrame(false);
	first.scan->setScanRange(5, std::numeric_limits<float>::quiet_NaN());
	const auto r0 = fusion.process(*first.scan, *first.stereo, "frame 0", first.odometry);
	ASSERT_EQ(r0.warnings.size(), 1u);
	ASSERT_EQ(logged.size(), 1u);	// INFO and above by default: no figures
	EXPECT_EQ(logged[0].first, mrpt::system::LVL_WARN);
	EXPECT_NE(logged[0].second.find(r0.warnings[0]), std::string::npos) << logged[0].second;

	logged.clear();
	fusion.setMinLoggingLevel(mrpt::system::LVL_DEBUG);
	const auto second = sim.simulateNextFrame(false);
	const auto r1 = fusion.process(*second.scan, *second.stereo, "frame 1", second.odometry);
	ASSERT_EQ(logged.size(), 1u);
	EXPECT_EQ(logged[0].first, mrpt::system::LVL_DEBUG);
	const std::string expected = "frame 1: " + std::to_string(r1.segments.size()) + " segments; ";
	EXPECT_EQ(logged[0].second.rfind(expected, 0), 0u) << logged[0].second;
	// The cube the laser misses: bearings vision brought nearer, as counted.
	const size_t shortened = r1.shortenedBearings(*second.scan);
	EXPECT_GT(shortened, 0u);
	EXPECT_NE(logged[0].second.find("; " + std::to_string(shortened) + " of " +
				  std::to_string(second.scan->getScanSize()) + " bearings nearer than the laser"),
		std::string::npos)
		<< logged[0].second;
}

// A laser mounted upside down (rolled 180 degrees about its x axis, as many
// robots carry one), or one that lists its rays clockwise (rightToLeft
// false), scans the same rays in the opposite order: its fused scan must be
// the upright one's, ray for ray reversed.
TEST(FusionPipeline, AnUpsideDownOrClockwiseLaserFusesTheSameRays)
{
	const auto world = simulation::generateRandomWorld(3);
	simulation::CStereoLaserSimulator sim(world, simulation::CStereoLaserSimulator::TOptions());
	const auto f = sim.simulateNextFrame(false);
	const auto& upright = *f.scan;
	const size_t n = upright.getScanSize();
	auto reversed = [&](mrpt::obs::CObservation2DRangeScan scan) {
		for (size_t i = 0; i < n; i++)
		{
			scan.setScanRange(i, upright.getScanRange(n - 1 - i));
			scan.setScanRangeValidity(i, upright.getScanRangeValidity(n - 1 - i));
		}
		return scan;
	};
	auto upsideDown = reversed(upright);
	const auto& p = upright.sensorPose;
	upsideDown.sensorPose = mrpt::poses::CPose3D(p.x(), p.y(), p.z(), p.yaw(), p.pitch(), p.roll() + M_PI);
	auto clockwise = reversed(upright);
	clockwise.rightToLeft = false;

	const auto expected = fusion::CLaserStereoFusion().process(upright, *f.stereo, "upright");
	size_t shortened = 0;
	for (size_t i = 0; i < n; i++) shortened += expected.fused->getScanRange(i) < laserRangeOrMax(upright, i);
	EXPECT_GT(shortened, 5u) << "vision shortened too few rays to compare";
	for (const auto* scan : {&upsideDown, &clockwise})
	{
		SCOPED_TRACE(scan == &clockwise ? "clockwise" : "upside down");
		const auto r = fusion::CLaserStereoFusion().process(*scan, *f.stereo, "frame");
		EXPECT_EQ(r.segments.size(), expected.segments.size());
		for (size_t i = 0; i < n; i++)
			EXPECT_NEAR(r.fused->getScanRange(n - 1 - i), expected.fused->getScanRange(i), 1e-4) << "ray " << i;
	}
}

// The same test rooms seen by a 0.25-degree laser over 270 degrees (a
// Hokuyo's): each bearing's 1-degree bin (ScanFusion's bin_width_deg) still
// gathers the points a 1-degree bearing would. Measured (lvf-fuse on the
// same rooms simulated so): recall 0.900, phantom rate 0.021; with bins as
// narrow as the rays 0.726, 0.017 (the 1-degree laser: 0.908, 0.017).
TEST(FusionPipeline, AQuarterDegreeLaserFindsWhatItMissesAsWell)
{
	simulation::CStereoLaserSimulator::TOptions sensors;
	sensors.laser.resolutionDeg = 0.25;
	sensors.laser.apertureDeg = 270;
	auto run = [&](double binWidthDeg) {
		fusion::CLaserStereoFusion::TOptions options;
		options.fusion.binWidthDeg = binWidthDeg;
		metrics::FusionScore total;
		fusion::CLaserStereoFusion::StageTimes times;
		size_t frames = 0;
		for (uint32_t seed = 1; seed <= 6; seed++) total.add(fuseWorld(seed, times, frames, sensors, options));
		std::cout << "bins of " << binWidthDeg << " deg: hidden " << total.hidden << ", recall " << total.recall()
				  << ", phantom rate " << total.phantomRate() << " of " << total.inView << "\n";
		return total;
	};
	const auto degree = run(1.0), rayWide = run(0.25);
	ASSERT_GT(degree.hidden, 800u);
	EXPECT_GE(degree.recall(), 0.88);
	EXPECT_LE(degree.phantomRate(), 0.025);
	EXPECT_GE(degree.recall(), rayWide.recall() + 0.1);
}

// A rig that needs rectifying (a lens, the right camera toed in and rolled):
// rectification resamples both images, and interpolation averages the
// noise of neighbouring pixels, so the noise estimator (ImageNoise.h) reads
// less than half of it on the rectified image. The texture gates are set
// from the cameras' noise as taken, so they are the parallel rig's.
TEST(FusionPipeline, TextureGatesFollowTheCamerasNoiseThroughRectification)
{
	const auto world = simulation::generateRandomWorld(3);
	simulation::CStereoLaserSimulator::TOptions misaligned;
	misaligned.stereo.dist = {-0.15, 0.03, 0.001, -0.001, 0};
	misaligned.stereo.rightYawDeg = 1.5;
	misaligned.stereo.rightPitchDeg = -0.4;
	misaligned.stereo.rightRollDeg = 0.7;
	auto fuseFirstFrame = [&](const simulation::CStereoLaserSimulator::TOptions& sensors) {
		simulation::CStereoLaserSimulator sim(world, sensors);
		const auto f = sim.simulateNextFrame(false);
		return fusion::CLaserStereoFusion().process(*f.scan, *f.stereo, "frame 0");
	};
	const auto parallel = fuseFirstFrame({}), rectified = fuseFirstFrame(misaligned);
	ASSERT_TRUE(rectified.left.size() == parallel.left.size());
	const double onRectified = evaluation::estimateNoiseStd(rectified.left);
	std::cout << "noise std: parallel rig " << parallel.evaluation.noiseStd << ", rectified rig "
			  << rectified.evaluation.noiseStd << " (on its rectified image " << onRectified << ")\n";
	EXPECT_NEAR(rectified.evaluation.noiseStd, parallel.evaluation.noiseStd, 0.1 * parallel.evaluation.noiseStd);
	EXPECT_DOUBLE_EQ(rectified.evaluation.textureGate, parallel.evaluation.textureGate);
	EXPECT_LT(onRectified, 0.6 * rectified.evaluation.noiseStd);
}
