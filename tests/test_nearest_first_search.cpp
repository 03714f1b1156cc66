// Nearest first (FocusedEpipolarSearch::TOptions::nearestFirstLevels): the
// search's grid rows taken coarse rows first, each later pass searching a
// pixel only in front of what the passes before it found on its bearing.
// NearestPerBearing's bound against constructed points; then the whole
// fusion with and without it on seeded rooms it was not tuned on, against
// the simulator's truth scans: the same obstacles from far fewer matches.

#include <gtest/gtest.h>
#include <lvfusion/depth/NearestPerBearing.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/RandomWorld.h>

#include <cmath>

using namespace lvf;

namespace
{
const Eigen::Vector3d kCamera(0.1, 0.05, 1.0);

/** The robot-frame point at horizontal distance d and bearing a [deg] from
 * the camera, at height z. */
Eigen::Vector3d fromCamera(double d, double bearingDeg, double z)
{
	const double a = bearingDeg * M_PI / 180;
	return {kCamera.x() + d * std::cos(a), kCamera.y() + d * std::sin(a), z};
}

/** A ray from the camera on bearing a [deg], sloping down by `slope`. */
Eigen::Vector3d ray(double bearingDeg, double slope)
{
	const double a = bearingDeg * M_PI / 180;
	return {std::cos(a), std::sin(a), -slope};
}
}  // namespace

TEST(NearestPerBearing, BoundsABearingAtItsKthNearestPointWhateverTheHeight)
{
	depth::NearestPerBearing nearest(kCamera, 3);
	// Four points on one bearing at various heights, one beside it.
	for (const auto& [d, z] : {std::pair{2.0, 0.3}, {1.5, 0.9}, {3.0, 0.1}, {2.5, 0.6}})
		nearest.add(fromCamera(d, 20.1, z));
	nearest.add(fromCamera(0.8, 25.1, 0.5));
	nearest.finish();
	// The third nearest of 1.5, 2.0, 2.5, 3.0, along any ray of that bearing.
	EXPECT_NEAR(nearest.along(ray(20.1, 0.0)), 2.5, 1e-9);
	EXPECT_NEAR(nearest.along(ray(20.1, 0.4)), 2.5, 1e-9);
	// One point is not enough there; nothing was found on a third bearing.
	EXPECT_TRUE(std::isinf(nearest.along(ray(25.1, 0.2))));
	EXPECT_TRUE(std::isinf(nearest.along(ray(-40.1, 0.2))));
}

TEST(NearestPerBearing, PointsAddedLaterTightenTheBoundAtTheNextFinish)
{
	depth::NearestPerBearing nearest(kCamera, 2);
	EXPECT_TRUE(std::isinf(nearest.along(ray(30.1, 0.2))));
	nearest.add(fromCamera(3.0, 30.1, 0.5));
	nearest.add(fromCamera(2.0, 30.1, 0.5));
	nearest.finish();
	EXPECT_NEAR(nearest.along(ray(30.1, 0.2)), 3.0, 1e-9);
	// A later pass's point: the old bound stands until finish().
	nearest.add(fromCamera(1.0, 30.1, 0.5));
	EXPECT_NEAR(nearest.along(ray(30.1, 0.2)), 3.0, 1e-9);
	nearest.finish();
	EXPECT_NEAR(nearest.along(ray(30.1, 0.2)), 2.0, 1e-9);
}

TEST(NearestPerBearing, BearingsAQuarterDegreeApartAreBoundedApart)
{
	depth::NearestPerBearing nearest(kCamera, 1);
	nearest.add(fromCamera(1.0, 10.1, 0.5));
	nearest.add(fromCamera(4.0, 10.4, 0.5));
	nearest.finish();
	EXPECT_NEAR(nearest.along(ray(10.1, 0.2)), 1.0, 1e-9);
	EXPECT_NEAR(nearest.along(ray(10.4, 0.2)), 4.0, 1e-9);
	// Across the -pi / +pi seam too.
	depth::NearestPerBearing behind(kCamera, 1);
	behind.add(fromCamera(2.0, 179.9, 0.5));
	behind.finish();
	EXPECT_NEAR(behind.along(ray(179.9, 0.1)), 2.0, 1e-9);
	EXPECT_TRUE(std::isinf(behind.along(ray(-179.9, 0.1))));
}

namespace
{
struct RoomsFused
{
	metrics::FusionScore score;
	size_t accepted = 0, nccEvaluations = 0;
	std::vector<float> fused;  //!< every frame's fused ranges, in view or not (NaN)
};

RoomsFused fuseRooms(const std::vector<uint32_t>& seeds, int nearestFirstLevels)
{
	fusion::CLaserStereoFusion::TOptions options;
	options.depth.nearestFirstLevels = nearestFirstLevels;
	RoomsFused run;
	for (uint32_t seed : seeds)
	{
		simulation::CStereoLaserSimulator sim(simulation::generateRandomWorld(seed), {});
		fusion::CLaserStereoFusion fusion(options);
		for (size_t k = 0; k < sim.frameCount(); k++)
		{
			const auto f = sim.simulateNextFrame(false);
			const auto r = fusion.process(*f.scan, *f.stereo, "frame", f.odometry);
			const auto inView =
				metrics::bearingsInView(*f.scan, f.truthScan, *f.stereo, options.band, options.depth.zMax);
			run.score.add(metrics::scoreFusedScan(*f.scan, *r.fused, f.truthScan, inView, options.depth.zMax));
			run.accepted += r.search.stats.accepted;
			run.nccEvaluations += r.search.stats.disparitiesTested;
			for (size_t i = 0; i < r.fused->getScanSize(); i++)
				run.fused.push_back(inView[i] ? r.fused->getScanRange(i) : NAN);
		}
	}
	return run;
}
}  // namespace

TEST(NearestFirstSearch, FindsTheSameObstaclesFromFarFewerMatches)
{
	const std::vector<uint32_t> rooms{41, 42, 43, 44, 45, 46, 47, 48};
	const RoomsFused onePass = fuseRooms(rooms, 0), nearestFirst = fuseRooms(rooms, 2);
	ASSERT_EQ(onePass.fused.size(), nearestFirst.fused.size());
	size_t inView = 0, same = 0;  // bearings in the cameras' view
	for (size_t i = 0; i < onePass.fused.size(); i++)
	{
		if (std::isnan(onePass.fused[i])) continue;
		inView++;
		same += std::abs(onePass.fused[i] - nearestFirst.fused[i]) <= 0.02f;
	}
	auto show = [](const char* name, const RoomsFused& r) {
		std::cout << name << ": recall " << r.score.recall() << " of " << r.score.hidden << ", phantom rate "
				  << r.score.phantomRate() << " of " << r.score.inView << "; " << r.accepted
				  << " points from " << r.nccEvaluations << " NCC evaluations\n";
	};
	show("one pass", onePass);
	show("nearest first", nearestFirst);
	std::cout << same << " of " << inView << " bearings in view within 2 cm of each other\n";
	// Measured: 1207 of 1228 bearings within 2 cm of each other; recall
	// 0.866 of 522 hidden bearings both ways, phantom rate 0.0122 -> 0.0110
	// of 817; 0.57 of the points from 0.94 of the NCC evaluations (what it
	// saves is mostly the verification of matches on obstacles already
	// found, not the scoring).
	EXPECT_GT(inView, 1000u);
	EXPECT_GE(double(same), 0.95 * double(inView));
	EXPECT_GE(nearestFirst.score.recall(), onePass.score.recall() - 0.01);
	EXPECT_LE(nearestFirst.score.phantomRate(), onePass.score.phantomRate() + 0.005);
	EXPECT_LT(double(nearestFirst.accepted), 0.75 * double(onePass.accepted));
	EXPECT_LT(nearestFirst.nccEvaluations, onePass.nccEvaluations);
}
