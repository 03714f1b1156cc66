// Stage 1, scan -> line segments (paper §3), against ground truth: simulated
// scans whose faces are known exactly. (Real logs, and the options through
// INI: test_line_segments_real_logs.cpp.)

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <lvfusion/lines/LineFit.h>
#include <lvfusion/lines/ScanLineExtractor.h>
#include <lvfusion/simulation/SimulatedLaser.h>
#include <lvfusion/simulation/WorldGeometry.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>

using lvf::lines::LineSegment;
using lvf::lines::ScanLineExtractor;
using namespace lvf::simulation;

namespace
{
constexpr double kDeg = M_PI / 180;

// ---------------------------------------------------------------------------
// Ground truth from the simulator's own geometry
// ---------------------------------------------------------------------------

/** One face of a box: the side `side` (+1/-1) of local axis `axis` (0, 1). */
struct FaceKey
{
	int box = -1, axis = 0, side = 0;
	bool operator<(const FaceKey& o) const
	{
		return std::tie(box, axis, side) < std::tie(o.box, o.axis, o.side);
	}
	bool operator==(const FaceKey& o) const
	{
		return box == o.box && axis == o.axis && side == o.side;
	}
	bool valid() const { return box >= 0; }
};

/** A face's line in the robot frame: normal.dot(p) == offset, normal outward
 * (towards the side the laser sees it from). */
struct FaceLine
{
	Eigen::Vector2d normal, dir;
	double offset;
	double along(const Eigen::Vector2d& p) const { return dir.dot(p); }
	double distance(const Eigen::Vector2d& p) const { return normal.dot(p) - offset; }
	/** Where the ray origin + t (cos b, sin b) meets the line; t < 0: never. */
	Eigen::Vector2d meet(const Eigen::Vector2d& origin, double bearing, double& t) const
	{
		const Eigen::Vector2d d(std::cos(bearing), std::sin(bearing));
		const double den = normal.dot(d);
		t = std::abs(den) < 1e-12 ? -1 : (offset - normal.dot(origin)) / den;
		return origin + t * d;
	}
};

/** A simulated laser on a robot at a known pose, with noise-free ray casts
 * of the same geometry at any bearing: the truth the segments are held to.
 * Everything is expressed in the robot frame, as the segments are. */
class Scene
{
   public:
	Scene(const std::string& yaml, const mrpt::poses::CPose3D& robot)
		: m_world(lvf::test::worldFromText(yaml)),
		  m_geometry(m_world),
		  m_robot(robot)
	{
		m_laserOptions = SimulatedLaser::TOptions();  // SICK PLS, 5 cm noise
		m_sensor = m_robot + m_laserOptions.sensorPose();
		m_origin = Eigen::Vector2d(m_laserOptions.poseX, m_laserOptions.poseY);
	}

	mrpt::obs::CObservation2DRangeScan::Ptr scan(double noiseStd, uint64_t seed) const
	{
		auto o = m_laserOptions;
		o.noiseStd = noiseStd;
		return SimulatedLaser(o).scan(m_geometry, m_robot, seed, {});
	}

	/** The face the noise-free ray at `bearing` (sensor frame) hits within
	 * the maximum range, as the simulated laser casts it. */
	FaceKey faceAt(double bearing) const
	{
		const Eigen::Vector3d origin(m_sensor.x(), m_sensor.y(), m_sensor.z());
		double dx, dy, dz;
		m_sensor.composePoint(std::cos(bearing), std::sin(bearing), 0, dx, dy, dz);
		const RayHit hit = m_geometry.castRay(
			origin, Eigen::Vector3d(dx, dy, dz) - origin, m_laserOptions.maxRange);
		if (!hit.hit() || hit.box < 0 || hit.axis == 2) return {};
		return {hit.box, hit.axis, hit.side > 0 ? 1 : -1};
	}

	FaceLine line(const FaceKey& f) const
	{
		const Box& b = m_world.boxes[static_cast<size_t>(f.box)];
		const double half = 0.5 * (f.axis == 0 ? b.sizeX : b.sizeY);
		const double a = b.yaw + (f.axis == 0 ? 0.0 : M_PI_2);
		// Outward normal and a point of the face, world frame, then robot.
		const Eigen::Vector2d nw = f.side * Eigen::Vector2d(std::cos(a), std::sin(a));
		const Eigen::Vector2d pw = Eigen::Vector2d(b.x, b.y) + half * nw;
		const auto p = m_robot.inverseComposePoint(mrpt::math::TPoint3D(pw.x(), pw.y(), 0));
		const double yaw = m_robot.yaw();
		const Eigen::Vector2d n(
			std::cos(-yaw) * nw.x() - std::sin(-yaw) * nw.y(),
			std::sin(-yaw) * nw.x() + std::cos(-yaw) * nw.y());
		FaceLine l;
		l.normal = n;
		l.dir = Eigen::Vector2d(-n.y(), n.x());
		l.offset = n.dot(Eigen::Vector2d(p.x, p.y));
		return l;
	}

	int boxIndex(const std::string& name) const
	{
		for (size_t i = 0; i < m_world.boxes.size(); i++)
			if (m_world.boxes[i].name == name) return static_cast<int>(i);
		throw std::runtime_error("no box " + name);
	}

	std::string faceName(const FaceKey& f) const
	{
		return m_world.boxes[static_cast<size_t>(f.box)].name + "/" +
			(f.axis == 0 ? "x" : "y") + (f.side > 0 ? "+" : "-");
	}

	/** The bearing between b0 (not on `face`) and b1 (on it) where the
	 * visible part of the face begins: 40 bisections, 1e-12 rad. */
	double boundary(const FaceKey& face, double b0, double b1) const
	{
		for (int k = 0; k < 40; k++)
		{
			const double m = 0.5 * (b0 + b1);
			(faceAt(m) == face ? b1 : b0) = m;
		}
		return b1;
	}

	const Eigen::Vector2d& origin() const { return m_origin; }
	double noiseStd() const { return m_laserOptions.noiseStd; }

   private:
	World m_world;
	WorldGeometry m_geometry;
	mrpt::poses::CPose3D m_robot, m_sensor;
	SimulatedLaser::TOptions m_laserOptions;
	Eigen::Vector2d m_origin;
};

/** A maximal run of consecutive rays that hit one face: what one segment
 * should stand for. Its true visible extent and the beam spacing at its ends
 * come from the noise-free geometry. */
struct VisibleRun
{
	FaceKey face;
	FaceLine line;
	size_t firstRay = 0, lastRay = 0;
	Eigen::Vector2d trueStart, trueEnd;	 //!< exact ends of the visible part
	double spacingStart = 0, spacingEnd = 0;	 //!< gap between rays there, along the line [m]
	double incidenceStart = 0, incidenceEnd = 0;  //!< angle ray/normal [rad]
	double predictedAngleStd = 0;  //!< of a TLS fit at the scan's noise [rad]
	double predictedStartStd = 0, predictedEndStd = 0;	//!< perpendicular [m]
	/** The end is a corner: the next ray's face touches this one there
	 * (else the end is an occlusion edge or the edge of the scan). */
	bool cornerStart = false, cornerEnd = false;
	double length() const { return (trueEnd - trueStart).norm(); }
	size_t rays() const { return lastRay - firstRay + 1; }
};

std::vector<VisibleRun> visibleRuns(
	const Scene& scene, const mrpt::obs::CObservation2DRangeScan& scan,
	double noiseStd)
{
	const size_t n = scan.getScanSize();
	std::vector<FaceKey> label(n);
	for (size_t i = 0; i < n; i++) label[i] = scene.faceAt(scan.getScanAngle(i));
	std::vector<VisibleRun> runs;
	const Eigen::Vector2d o = scene.origin();
	for (size_t i = 0; i < n;)
	{
		size_t j = i;
		while (j + 1 < n && label[j + 1] == label[i]) j++;
		if (label[i].valid())
		{
			VisibleRun r;
			r.face = label[i];
			r.line = scene.line(r.face);
			r.firstRay = i;
			r.lastRay = j;
			double t;
			// Exact ends: where the view of the face begins between the
			// last ray off it and the first on it (or the edge of the scan).
			const double bStart = i == 0 ? scan.getScanAngle(0)
				: scene.boundary(r.face, scan.getScanAngle(i - 1), scan.getScanAngle(i));
			const double bEnd = j + 1 == n ? scan.getScanAngle(n - 1)
				: scene.boundary(r.face, scan.getScanAngle(j + 1), scan.getScanAngle(j));
			r.trueStart = r.line.meet(o, bStart, t);
			r.trueEnd = r.line.meet(o, bEnd, t);
			// Beam spacing at each end: between the extreme ray on the face
			// and the next ray outwards, both met with the face's line.
			auto spacing = [&](size_t inner, long outer) {
				if (outer < 0 || outer >= static_cast<long>(n)) return 0.0;
				double t1, t2;
				const auto p1 = r.line.meet(o, scan.getScanAngle(inner), t1);
				const auto p2 = r.line.meet(o, scan.getScanAngle(static_cast<size_t>(outer)), t2);
				return t2 > 0 ? (p1 - p2).norm() : std::numeric_limits<double>::infinity();
			};
			r.spacingStart = spacing(i, static_cast<long>(i) - 1);
			r.spacingEnd = spacing(j, static_cast<long>(j) + 1);
			auto incidence = [&](size_t ray) {
				const double b = scan.getScanAngle(ray);
				return std::acos(std::min(1.0, std::abs(r.line.normal.dot(
					Eigen::Vector2d(std::cos(b), std::sin(b))))));
			};
			r.incidenceStart = incidence(i);
			r.incidenceEnd = incidence(j);
			// What a total least squares fit can achieve at this noise (first
			// order): range noise s along the ray is s cos(incidence) across
			// the line; the direction's variance is that of a regression
			// slope, sum(w_k^2 s_k^2), w_k = (u_k - mean u) / sum((u - mean u)^2).
			std::vector<double> u, s;
			for (size_t k = i; k <= j; k++)
			{
				double tk;
				u.push_back(r.line.along(r.line.meet(o, scan.getScanAngle(k), tk)));
				s.push_back(noiseStd * std::cos(incidence(k)));
			}
			const double mean = std::accumulate(u.begin(), u.end(), 0.0) / u.size();
			double suu = 0, varOffset = 0, varAngle = 0;
			for (double x : u) suu += (x - mean) * (x - mean);
			for (size_t k = 0; k < u.size(); k++)
			{
				varOffset += s[k] * s[k] / (u.size() * u.size());
				if (suu > 0) varAngle += std::pow((u[k] - mean) / suu * s[k], 2);
			}
			r.predictedAngleStd = std::sqrt(varAngle);
			auto endStd = [&](const Eigen::Vector2d& p) {
				return std::sqrt(varOffset + varAngle * std::pow(r.line.along(p) - mean, 2));
			};
			r.predictedStartStd = endStd(r.trueStart);
			r.predictedEndStd = endStd(r.trueEnd);
			runs.push_back(r);
		}
		i = j + 1;
	}
	for (size_t k = 0; k + 1 < runs.size(); k++)
		if (runs[k + 1].firstRay == runs[k].lastRay + 1)
		{
			// Touching faces share the corner point.
			const bool corner = std::abs(runs[k + 1].line.distance(runs[k].trueEnd)) < 0.01;
			runs[k].cornerEnd = runs[k + 1].cornerStart = corner;
		}
	return runs;
}

double angleToLine(const LineSegment& s, const FaceLine& l)
{
	return std::acos(std::min(1.0, std::abs(s.direction().dot(l.dir))));
}

/** The run most of a segment's rays belong to, and that share; -1: none. */
int majorityRun(
	const LineSegment& s, const std::vector<VisibleRun>& runs, double& share)
{
	std::map<int, size_t> votes;
	for (size_t ray = s.firstIndex; ray <= s.lastIndex; ray++)
		for (size_t k = 0; k < runs.size(); k++)
			if (ray >= runs[k].firstRay && ray <= runs[k].lastRay)
				votes[static_cast<int>(k)]++;
	int best = -1;
	size_t bestVotes = 0;
	for (const auto& [k, v] : votes)
		if (v > bestVotes) best = k, bestVotes = v;
	share = static_cast<double>(bestVotes) /
		static_cast<double>(s.lastIndex - s.firstIndex + 1);
	return best;
}

/** Errors over many checked faces, for the report. */
struct ErrorStats
{
	size_t runs = 0, segments = 0, mixedSegments = 0;
	size_t shortFaces = 0, shortFacesResolved = 0;	// 0.5 .. 1 m, with noise
	size_t checks = 0, overBound = 0;  // accuracy checks, and those failed
	double worstOverBound = 0;	// the largest measured / bound
	double worstAngleDeg = 0, worstPerp = 0, worstAlong = 0;
	double worstAlongOverSpacing = 0;  // occlusion edges and scan edges
	std::vector<double> perp, angleDeg, alongOverSpacing;

	static double median(std::vector<double> v)
	{
		if (v.empty()) return 0.0;
		std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
		return v[v.size() / 2];
	}
	void print(const std::string& what) const
	{
		std::cout << "[ " << what << " ] " << runs << " faces checked";
		if (shortFaces > 0)
			std::cout << " (of which " << shortFacesResolved << " of " << shortFaces
					  << " faces of 0.5-1 m resolved as one segment)";
		std::cout << ", " << checks << " accuracy checks (" << overBound
				  << " over their bound, worst at " << worstOverBound << " x it)";
		std::cout << ", " << segments
				  << " segments (" << mixedSegments << " on two faces): direction error median "
				  << median(angleDeg) << " deg, worst " << worstAngleDeg
				  << " deg; endpoint error across the line median " << 100 * median(perp)
				  << " cm, worst " << 100 * worstPerp << " cm; along the line worst "
				  << 100 * worstAlong << " cm, median " << median(alongOverSpacing)
				  << " and worst " << worstAlongOverSpacing
				  << " x the beam spacing there (corners excluded)" << std::endl;
	}
};

/** The faces of the scene with a long enough visible run each get exactly
 * one segment, lying on that face, as accurate as the noise allows. */
void checkSegmentsAgainstFaces(
	const Scene& scene, const mrpt::obs::CObservation2DRangeScan& scan,
	double noiseStd, const std::vector<LineSegment>& segments,
	ErrorStats& stats, const std::string& context)
{
	const auto runs = visibleRuns(scene, scan, noiseStd);
	const ScanLineExtractor::TOptions defaults;
	const bool noisy = noiseStd > 0;
	// A segment stands for the face that holds most of its rays. Without
	// noise that is 80% at least (a corner ray may go either way). With
	// 5 cm of noise the returns near a corner fit either face, and next to
	// a sliver of a face (a box side seen nearly edge-on, 5 rays) the best
	// breakpoint can be several rays off: a segment with less than 2/3 of
	// its rays on one face stands for none, and must stay rare.
	const double matchShare = noisy ? 2.0 / 3.0 : 0.8;
	// Without noise every bound holds. With noise the bounds are 4 std of
	// a first-order prediction (or the beam spacing plus 3 std), which does
	// not know that a corner return may go to the wrong face: the caller
	// allows 2% of the checks over their bound, none by 2x.
	auto check = [&](double value, double bound, const std::string& what) {
		stats.checks++;
		stats.worstOverBound = std::max(stats.worstOverBound, value / bound);
		if (value <= bound) return;
		stats.overBound++;
		if (noisy)
			EXPECT_LE(value, 2 * bound) << what;
		else
			EXPECT_LE(value, bound) << what;
	};
	std::vector<std::vector<size_t>> segmentsOfRun(runs.size());
	for (size_t k = 0; k < segments.size(); k++)
	{
		double share = 0;
		const int run = majorityRun(segments[k], runs, share);
		ASSERT_GE(run, 0) << context << ": segment " << k << " on no face";
		stats.segments++;
		if (share < matchShare)
		{
			stats.mixedSegments++;
			EXPECT_TRUE(noisy) << context << ": segment " << k << " spans faces, "
							   << 100 * share << "% on one";
			continue;
		}
		segmentsOfRun[static_cast<size_t>(run)].push_back(k);
	}
	for (size_t r = 0; r < runs.size(); r++)
	{
		const VisibleRun& run = runs[r];
		// "Visible over a reasonable length": 0.5 m and twice the points a
		// segment needs, so that the run is a wall or a box side and not a
		// sliver seen edge-on. With 5 cm of noise a 0.6 m box side seen from
		// 1 m has its 30 returns in a band 10 cm wide, and a sliver of the
		// next side 3 returns long lies within that band: it cannot be told
		// apart, and the pieces may not come together. So with noise, faces
		// of 1 m and more must get exactly one segment, and of the shorter
		// ones 90% (checked by the caller); either way, one that got one
		// segment must meet the accuracy bounds below.
		if (run.length() < 0.5 || run.rays() < 2 * static_cast<size_t>(defaults.minPoints))
			continue;
		const std::string what = context + ", " + scene.faceName(run.face) +
			" (rays " + std::to_string(run.firstRay) + ".." + std::to_string(run.lastRay) + ")";
		if (noisy && run.length() < 1.0)
		{
			stats.shortFaces++;
			if (segmentsOfRun[r].size() != 1) continue;
			stats.shortFacesResolved++;
		}
		ASSERT_EQ(segmentsOfRun[r].size(), 1u) << what;
		const LineSegment& s = segments[segmentsOfRun[r][0]];
		stats.runs++;

		// Direction: 1 deg, or 4 std of what a TLS fit of these points can
		// do if that is more. With 5 cm noise a 0.6 m box side of ~10 points
		// has a 5 deg std, and no method gets it within 1 deg; a 6 m wall
		// has 0.2 deg. (4 std: some 500 faces are checked, and the std is a
		// first-order prediction.)
		const double angle = angleToLine(s, run.line);
		const double angleBound = std::max(1 * kDeg, 4 * run.predictedAngleStd);
		check(angle, angleBound, what + " direction");
		stats.worstAngleDeg = std::max(stats.worstAngleDeg, angle / kDeg);
		stats.angleDeg.push_back(angle / kDeg);
		// The normal faces the sensor, like the face's outward normal.
		EXPECT_GT(s.normal.dot(run.line.normal), 0.9) << what;

		for (int end = 0; end < 2; end++)
		{
			const Eigen::Vector2d& p = end ? s.end : s.start;
			const Eigen::Vector2d& truth = end ? run.trueEnd : run.trueStart;
			const std::string which = what + (end ? " end" : " start");
			// Across the line: 3 cm, or 4 std of the fitted line there.
			const double perp = std::abs(run.line.distance(p));
			const double perpBound = std::max(
				0.03, 4 * (end ? run.predictedEndStd : run.predictedStartStd));
			check(perp, perpBound, which + " across");
			stats.worstPerp = std::max(stats.worstPerp, perp);
			stats.perp.push_back(perp);
			// Along the line an endpoint is the projection of the last point
			// on the face, and the face's true end lies somewhere between
			// that ray and the next: nothing tells where, so the beam
			// spacing there is the resolution. With noise the point also
			// slides along the line by the range noise times
			// sin(incidence), and the projection onto a line tilted by the
			// direction error adds noise x cos(incidence) x tan(error):
			// 3 std of those on top. At a corner the ray nearest it may hit
			// within a hair of both faces and go to the other one: a beam
			// spacing more; and with noise the returns within ~3 std of the
			// corner fit either face: 3 std more.
			const double spacing = end ? run.spacingEnd : run.spacingStart;
			const double incidence = end ? run.incidenceEnd : run.incidenceStart;
			const bool corner = end ? run.cornerEnd : run.cornerStart;
			const double along = std::abs(run.line.along(p - truth));
			const double alongBound = spacing +
				3 * noiseStd * (std::sin(incidence) + std::cos(incidence) * std::tan(angleBound)) +
				(corner ? spacing + 3 * noiseStd : 0.0) + 1e-6;
			check(along, alongBound,
				which + " along, spacing " + std::to_string(spacing) + (corner ? ", a corner" : ""));
			stats.worstAlong = std::max(stats.worstAlong, along);
			if (spacing > 0 && std::isfinite(spacing) && !corner)
			{
				stats.alongOverSpacing.push_back(along / spacing);
				stats.worstAlongOverSpacing =
					std::max(stats.worstAlongOverSpacing, along / spacing);
			}
		}
	}
}

// A 6 m x 6 m room with the four floor boxes of box_room.yaml (Fig. 7 of the
// paper): walls 0.1 m thick, so the inner faces are at 0.05 and 5.95.
const char* kRoom =
	"name: room\n"
	"walls:\n"
	"  - {from: [0, 0], to: [6, 0]}\n"
	"  - {from: [6, 0], to: [6, 6]}\n"
	"  - {from: [6, 6], to: [0, 6]}\n"
	"  - {from: [0, 6], to: [0, 0]}\n"
	"boxes:\n"
	"  - {name: floor_a, pose: [2.2, 2.6, 0], size: [0.6, 0.6, 0.5]}\n"
	"  - {name: floor_b, pose: [4.2, 3.3, 20], size: [0.7, 0.5, 0.8]}\n"
	"  - {name: floor_c, pose: [1.0, 4.5, 0], size: [0.6, 0.6, 0.6]}\n"
	"  - {name: floor_d, pose: [5.0, 1.5, -10], size: [0.5, 0.8, 0.6]}\n"
	"path: {poses: [[3, 0.6, 90]]}\n";

const std::vector<mrpt::poses::CPose3D> kRoomPoses = {
	{3.0, 0.6, 0, 90 * kDeg, 0, 0},	  {3.0, 2.0, 0, 90 * kDeg, 0, 0},
	{1.5, 1.5, 0, 45 * kDeg, 0, 0},	  {4.5, 4.5, 0, -135 * kDeg, 0, 0},
	{0.8, 3.0, 0, 10 * kDeg, 0, 0},	  {5.2, 2.5, 0, 160 * kDeg, 0, 0},
};

std::string poseText(const mrpt::poses::CPose3D& p)
{
	std::ostringstream s;
	s << "robot at (" << p.x() << ", " << p.y() << ", " << p.yaw() / kDeg << " deg)";
	return s.str();
}

}  // namespace

// ---------------------------------------------------------------------------
// The line fit
// ---------------------------------------------------------------------------

TEST(LineFit, TotalLeastSquaresRecoversKnownLines)
{
	// Points 2 cm either side of a known line in the pattern + - - + (no
	// mean, no trend along the line): the fit must find the line itself and
	// an RMS residual of exactly 2 cm, whatever its direction (a vertical
	// line is where y-on-x regression breaks down).
	for (const double angleDeg : {0.0, 30.0, 90.0, 135.0})
	{
		const double a = angleDeg * kDeg;
		const Eigen::Vector2d dir(std::cos(a), std::sin(a)), normal(-dir.y(), dir.x());
		const Eigen::Vector2d base(3.0, -1.0);
		auto point = [&](int i) {
			const double side = (i % 4 == 0 || i % 4 == 3) ? 0.02 : -0.02;
			return Eigen::Vector2d(base + (0.1 * i) * dir + side * normal);
		};
		lvf::lines::PointMoments all, first, rest;
		for (int i = 0; i < 40; i++)
		{
			all.add(point(i));
			(i < 12 ? first : rest).add(point(i));
		}
		const lvf::lines::LineFit fit = lvf::lines::fitLine(all);
		EXPECT_NEAR(std::abs(fit.normal.dot(normal)), 1.0, 1e-12) << angleDeg;
		EXPECT_NEAR(fit.distance(base), 0.0, 1e-9) << angleDeg;
		EXPECT_NEAR(fit.rmsResidual, 0.02, 1e-9) << angleDeg;
		EXPECT_NEAR(fit.sumSquaredResiduals(), 40 * 0.02 * 0.02, 1e-9) << angleDeg;
		// Taking away points that were added gives the fit of the rest.
		const lvf::lines::LineFit without = lvf::lines::fitLine(all - first);
		const lvf::lines::LineFit direct = lvf::lines::fitLine(rest);
		EXPECT_NEAR(without.rmsResidual, direct.rmsResidual, 1e-9) << angleDeg;
		EXPECT_NEAR(std::abs(without.normal.dot(direct.normal)), 1.0, 1e-12) << angleDeg;
	}
}

// ---------------------------------------------------------------------------
// Simulated scans against known faces
// ---------------------------------------------------------------------------

TEST(ScanLineExtractor, RoomWallsAndBoxesNoiseFree)
{
	const ScanLineExtractor extractor;	// defaults, as for the noisy scans
	ErrorStats stats;
	for (const auto& pose : kRoomPoses)
	{
		const Scene scene(kRoom, pose);
		const auto scan = scene.scan(0.0, 1);
		const auto segments = extractor.extract(*scan);
		checkSegmentsAgainstFaces(scene, *scan, 0.0, segments, stats, poseText(pose));
	}
	stats.print("noise-free room");
	// Without noise the fit is exact: far inside the 1 deg / 3 cm bounds.
	EXPECT_LT(stats.worstAngleDeg, 0.01);
	EXPECT_LT(stats.worstPerp, 1e-3);
	EXPECT_LE(stats.worstAlongOverSpacing, 1.0);
	EXPECT_GE(stats.runs, 20u);
	RecordProperty("noise_free_faces", static_cast<int>(stats.runs));
	RecordProperty("noise_free_worst_direction_error_deg", std::to_string(stats.worstAngleDeg));
	RecordProperty("noise_free_worst_endpoint_across_m", std::to_string(stats.worstPerp));
	RecordProperty("noise_free_worst_endpoint_along_over_spacing", std::to_string(stats.worstAlongOverSpacing));
}

TEST(ScanLineExtractor, RoomWallsAndBoxesWithPaperNoise)
{
	// The paper's SICK PLS: 5 cm range noise, the simulator's default.
	const ScanLineExtractor extractor;
	const double noise = SimulatedLaser::TOptions().noiseStd;
	ErrorStats stats;
	for (const auto& pose : kRoomPoses)
	{
		const Scene scene(kRoom, pose);
		for (uint64_t seed = 1; seed <= 5; seed++)
		{
			const auto scan = scene.scan(noise, seed);
			const auto segments = extractor.extract(*scan);
			checkSegmentsAgainstFaces(
				scene, *scan, noise, segments, stats,
				poseText(pose) + ", seed " + std::to_string(seed));
		}
	}
	stats.print("5 cm noise, room");
	EXPECT_GE(stats.runs, 100u);
	EXPECT_GE(stats.shortFacesResolved, (9 * stats.shortFaces + 9) / 10)
		<< "fewer than 90% of the 0.5-1 m faces resolved";
	EXPECT_LE(stats.overBound, stats.checks / 50) << "more than 2% of the accuracy checks over their bound";
	RecordProperty("noisy_accuracy_checks", static_cast<int>(stats.checks));
	RecordProperty("noisy_accuracy_checks_over_bound", static_cast<int>(stats.overBound));
	// Segments that straddle a corner: next to slivers of faces only.
	EXPECT_LE(stats.mixedSegments, stats.segments / 10) << "more than 10% of segments on two faces";
	RecordProperty("noisy_segments_on_two_faces", static_cast<int>(stats.mixedSegments));
	RecordProperty("noisy_segments", static_cast<int>(stats.segments));
	RecordProperty("noisy_short_faces_resolved", static_cast<int>(stats.shortFacesResolved));
	RecordProperty("noisy_short_faces", static_cast<int>(stats.shortFaces));
	RecordProperty("noisy_faces", static_cast<int>(stats.runs));
	RecordProperty("noisy_worst_direction_error_deg", std::to_string(stats.worstAngleDeg));
	RecordProperty("noisy_worst_endpoint_across_m", std::to_string(stats.worstPerp));
	RecordProperty("noisy_worst_endpoint_along_m", std::to_string(stats.worstAlong));
}

TEST(ScanLineExtractor, LongWallsWithPaperNoiseMeetTheTightBounds)
{
	// The four room walls alone, from the centre looking at a corner: two
	// whole 5.9 m faces of ~90 points each, where 1 deg and 3 cm are 6 and
	// ~3.5 std of the fit, so they are asserted as they are, with no
	// allowance for the noise (but see the 3 cm below). (A 3 m wall at 3 m, 45 points, has a direction std of
	// 0.4 deg: 1 deg would be only 2.5 std.)
	const char* room =
		"name: empty\n"
		"walls:\n"
		"  - {from: [0, 0], to: [6, 0]}\n"
		"  - {from: [6, 0], to: [6, 6]}\n"
		"  - {from: [6, 6], to: [0, 6]}\n"
		"  - {from: [0, 6], to: [0, 0]}\n"
		"path: {poses: [[3, 3, 0]]}\n";
	const ScanLineExtractor extractor;
	ErrorStats stats;
	size_t over3cm = 0;
	for (double yaw : {45.0, 135.0, -45.0, -135.0})
		for (uint64_t seed = 1; seed <= 10; seed++)
		{
			const mrpt::poses::CPose3D pose(3.0, 3.0, 0, yaw * kDeg, 0, 0);
			const Scene scene(room, pose);
			// The room looks the same from each corner: other noise for each.
			const auto scan = scene.scan(0.05, seed + 100 * static_cast<uint64_t>(yaw + 180));
			const auto segments = extractor.extract(*scan);
			const auto runs = visibleRuns(scene, *scan, 0.05);
			size_t wholeWalls = 0;
			for (const auto& run : runs)
			{
				if (run.length() < 5.0) continue;
				wholeWalls++;
				double share = 0;
				size_t matches = 0;
				for (const auto& s : segments)
				{
					if (majorityRun(s, runs, share) < 0 ||
						!(runs[static_cast<size_t>(majorityRun(s, runs, share))].face == run.face))
						continue;
					matches++;
					const double angle = angleToLine(s, run.line);
					EXPECT_LE(angle, 1 * kDeg);
					const double e0 = std::abs(run.line.distance(s.start));
					const double e1 = std::abs(run.line.distance(s.end));
					// 3 cm is ~3.5 std at the far ends: 1 endpoint in ~400
					// goes over it (by a fraction of a mm in a stress run of
					// 2000 scans), so 1% may, none by a third.
					over3cm += (e0 > 0.03) + (e1 > 0.03);
					EXPECT_LE(e0, 0.04);
					EXPECT_LE(e1, 0.04);
					stats.runs++;
					stats.worstAngleDeg = std::max(stats.worstAngleDeg, angle / kDeg);
					stats.angleDeg.push_back(angle / kDeg);
					stats.perp.push_back(e0);
					stats.perp.push_back(e1);
					stats.worstPerp = std::max({stats.worstPerp, e0, e1});
				}
				EXPECT_EQ(matches, 1u) << "yaw " << yaw << " seed " << seed;
			}
			EXPECT_EQ(wholeWalls, 2u) << "yaw " << yaw;
		}
	std::cout << "[ 5 cm noise, 5.9 m walls ] " << stats.runs << " walls: direction error median "
			  << ErrorStats::median(stats.angleDeg) << " deg, worst " << stats.worstAngleDeg
			  << " deg; endpoint error across the line median " << 100 * ErrorStats::median(stats.perp)
			  << " cm, worst " << 100 * stats.worstPerp << " cm, " << over3cm
			  << " over 3 cm" << std::endl;
	EXPECT_LE(over3cm, stats.perp.size() / 100);
	RecordProperty("long_walls_worst_direction_error_deg", std::to_string(stats.worstAngleDeg));
	RecordProperty("long_walls_worst_endpoint_across_m", std::to_string(stats.worstPerp));
}

TEST(ScanLineExtractor, CollinearBoxesWithAGapGiveTwoSegments)
{
	// Two boxes whose near faces lie on x = 2.2, y in [-1.25, -0.25] and
	// [0.25, 1.25]: 0.5 m apart, a wall 5 m further back seen through the
	// gap. The sphere-of-influence graph must cut at the gap (0.5 m, against
	// 4 cm between rays) and the merge pass must not rejoin the collinear
	// halves.
	const char* world =
		"name: gap\n"
		"boxes:\n"
		"  - {name: left, pose: [2.5, 0.75, 0], size: [0.6, 1.0, 0.5]}\n"
		"  - {name: right, pose: [2.5, -0.75, 0], size: [0.6, 1.0, 0.5]}\n"
		"walls:\n"
		"  - {name: back, from: [7.3, -4], to: [7.3, 4]}\n"
		"path: {poses: [[0, 0, 0]]}\n";
	const Scene scene(world, mrpt::poses::CPose3D());
	const FaceKey leftFace{scene.boxIndex("left"), 0, -1};
	const FaceKey rightFace{scene.boxIndex("right"), 0, -1};
	const FaceLine front = scene.line(leftFace);
	const ScanLineExtractor extractor;
	size_t spurious = 0, noisyScans = 0;
	for (double noise : {0.0, 0.05})
		for (uint64_t seed = 1; seed <= (noise > 0 ? 20u : 1u); seed++)
		{
			const auto scan = scene.scan(noise, seed);
			const auto segments = extractor.extract(*scan);
			const std::string what = "noise " + std::to_string(noise) + ", seed " + std::to_string(seed);
			// Per segment, its rays on each front face.
			std::vector<const LineSegment*> onRight, onLeft;
			size_t frontSegments = 0;
			for (const auto& s : segments)
			{
				size_t left = 0, right = 0;
				for (size_t ray = s.firstIndex; ray <= s.lastIndex; ray++)
				{
					const FaceKey f = scene.faceAt(scan->getScanAngle(ray));
					left += f == leftFace;
					right += f == rightFace;
				}
				// Never across the gap.
				EXPECT_TRUE(left == 0 || right == 0) << what << ": a segment bridges the gap";
				const size_t rays = s.lastIndex - s.firstIndex + 1;
				if (left + right > 0) frontSegments++;
				if (3 * left >= 2 * rays) onLeft.push_back(&s);
				if (3 * right >= 2 * rays) onRight.push_back(&s);
			}
			ASSERT_EQ(onRight.size(), 1u) << what;
			ASSERT_EQ(onLeft.size(), 1u) << what;
			// Without noise nothing else touches the front faces; with 5 cm,
			// a return of a box side seen edge-on next to the gap can make a
			// short segment with a few front returns (4 returns 2 cm apart
			// with 5 cm of noise have no direction): counted below.
			if (noise == 0)
				EXPECT_EQ(frontSegments, 2u) << what;
			else
			{
				noisyScans++;
				spurious += frontSegments - 2;
			}
			// Scan order is right to left: the right box (y < 0) first. The
			// ends at the gap are within a beam spacing (3.5 cm at 2.1 m),
			// plus 3 std of the range noise's along-line part at ~6 deg of
			// incidence and of the fit's tilt there (~1 cm).
			const LineSegment& right = *onRight[0];
			const LineSegment& left = *onLeft[0];
			const double tol = 0.036 + (noise > 0 ? 0.03 : 0.0);
			EXPECT_NEAR(right.end.y(), -0.25, tol) << what;
			EXPECT_NEAR(left.start.y(), 0.25, tol) << what;
			EXPECT_NE(right.cluster, left.cluster) << what;
			// Direction: 1 deg, or 4 std of a fit of these ~25 points over
			// 1 m (2 deg with 5 cm of noise) if more.
			const auto runs = visibleRuns(scene, *scan, noise);
			for (const auto& run : runs)
				if (run.face == leftFace || run.face == rightFace)
				{
					const LineSegment& s = run.face == leftFace ? left : right;
					const double bound = std::max(1 * kDeg, 4 * run.predictedAngleStd);
					EXPECT_LE(angleToLine(s, front), noise > 0 ? bound : 0.01 * kDeg) << what;
				}
		}
	std::cout << "[ collinear boxes ] 5 cm noise: " << spurious
			  << " extra short segments at the gap in " << noisyScans << " scans" << std::endl;
	EXPECT_LE(spurious, noisyScans / 10);
	RecordProperty("gap_spurious_segments", static_cast<int>(spurious));
}

TEST(ScanLineExtractor, ThresholdsFollowTheScansStatedNoise)
{
	// A box whose face stands 8 cm proud of a wall 3 m ahead (its near
	// face; walls are 0.1 m thick), seen by a
	// laser with 1 cm of noise that says so (stdError). At that noise the
	// face is a line of its own (8 std off the wall); at the thresholds for
	// the paper's 5 cm (split 15 cm) the wall's segment runs through it --
	// what put a model wall in front of Middlebury Motorcycle's returns.
	const char* world =
		"name: proud box\n"
		"boxes:\n"
		"  - {name: box, pose: [3.0, 0, 0], size: [0.16, 0.8, 0.5]}\n"
		"walls:\n"
		"  - {name: back, from: [3.05, -3], to: [3.05, 3], thickness: 0.1}\n"
		"path: {poses: [[0, 0, 0]]}\n";
	const Scene scene(world, mrpt::poses::CPose3D());
	const FaceKey face{scene.boxIndex("box"), 0, -1};
	const FaceLine front = scene.line(face);
	ASSERT_NEAR(front.offset * front.normal.x(), 2.92, 1e-9);
	// A segment on the face: most of its rays hit it, and it lies on it.
	auto faceSegments = [&](const ScanLineExtractor& extractor, const mrpt::obs::CObservation2DRangeScan& scan) {
		size_t found = 0;
		for (const auto& s : extractor.extract(scan))
		{
			size_t onFace = 0;
			for (size_t ray = s.firstIndex; ray <= s.lastIndex; ray++)
				onFace += scene.faceAt(scan.getScanAngle(ray)) == face;
			const bool onIt = 3 * onFace >= 2 * (s.lastIndex - s.firstIndex + 1) &&
				std::abs(front.distance(s.start)) < 0.02 && std::abs(front.distance(s.end)) < 0.02;
			found += onIt;
		}
		return found;
	};
	ScanLineExtractor::TOptions fixed;
	fixed.noiseFromScan = false;
	const ScanLineExtractor fromScan, atPaperNoise(fixed);
	size_t seen = 0, seenFixed = 0, seenUnstated = 0;
	const uint64_t seeds = 20;
	for (uint64_t seed = 1; seed <= seeds; seed++)
	{
		auto scan = scene.scan(0.01, seed);
		ASSERT_FLOAT_EQ(scan->stdError, 0.01f);
		seen += faceSegments(fromScan, *scan);
		seenFixed += faceSegments(atPaperNoise, *scan);
		// A scan that states no noise gets the fixed thresholds.
		scan->stdError = 0;
		seenUnstated += faceSegments(fromScan, *scan);
	}
	std::cout << "[ proud box ] face segments in " << seeds << " scans: from the scan's noise " << seen
			  << ", at 5 cm " << seenFixed << ", noise unstated " << seenUnstated << std::endl;
	EXPECT_EQ(seen, seeds);
	EXPECT_EQ(seenFixed, 0u);
	EXPECT_EQ(seenUnstated, 0u);
}

TEST(ScanLineExtractor, CornersGiveTwoSegmentsMeetingAtTheCorner)
{
	// A concave corner (room) and a convex one (a box turned 45 deg towards
	// the robot). The two segments' lines, intersected, give the corner.
	struct Case
	{
		const char* name;
		const char* key;  // for RecordProperty
		const char* yaml;
		mrpt::poses::CPose3D robot;
		Eigen::Vector2d cornerWorld;
	};
	const double c45 = 0.75 * std::sqrt(2.0);  // half diagonal of a 1.5 m square
	const std::vector<Case> cases = {
		{"concave room corner", "concave",
		 "name: c\nwalls:\n  - {from: [0, 6], to: [6, 6]}\n  - {from: [6, 6], to: [6, 0]}\n"
		 "path: {poses: [[0, 0, 0]]}\n",
		 mrpt::poses::CPose3D(3.0, 3.0, 0, 45 * kDeg, 0, 0), Eigen::Vector2d(5.95, 5.95)},
		{"convex box corner", "convex",
		 "name: c\nboxes:\n  - {pose: [3, 0, 45], size: [1.5, 1.5, 1]}\npath: {poses: [[0, 0, 0]]}\n",
		 mrpt::poses::CPose3D(), Eigen::Vector2d(3.0 - c45, 0.0)},
	};
	const ScanLineExtractor extractor;
	for (const auto& c : cases)
	{
		const Scene scene(c.yaml, c.robot);
		const auto cr = c.robot.inverseComposePoint({c.cornerWorld.x(), c.cornerWorld.y(), 0});
		const Eigen::Vector2d corner(cr.x, cr.y);
		double sumSq = 0, worst = 0;
		size_t count = 0, extra = 0;
		for (double noise : {0.0, 0.05})
			for (uint64_t seed = 1; seed <= (noise > 0 ? 20u : 1u); seed++)
			{
				const auto scan = scene.scan(noise, seed);
				const auto segments = extractor.extract(*scan);
				const std::string what = std::string(c.name) + ", noise " +
					std::to_string(noise) + ", seed " + std::to_string(seed);
				// The two faces meeting at the corner, in scan order, and the
				// segment that stands for each (2/3 of its rays on it).
				const auto runs = visibleRuns(scene, *scan, noise);
				size_t r = 0;
				while (r + 1 < runs.size() &&
					   !(runs[r].cornerEnd && (runs[r].trueEnd - corner).norm() < 0.01))
					r++;
				ASSERT_LT(r + 1, runs.size()) << what << ": no corner in the truth";
				const LineSegment* a = nullptr;
				const LineSegment* b = nullptr;
				size_t others = 0;
				for (const auto& s : segments)
				{
					double share = 0;
					const int k = majorityRun(s, runs, share);
					const bool onA = share >= 2.0 / 3.0 && k == static_cast<int>(r);
					const bool onB = share >= 2.0 / 3.0 && k == static_cast<int>(r + 1);
					if (onA && !a)
						a = &s;
					else if (onB && !b)
						b = &s;
					else if (onA || onB ||
							 (s.lastIndex + 5 >= runs[r].lastRay &&
							  s.firstIndex <= runs[r + 1].firstRay + 5))
						others++;  // a second segment on a face, or one at the corner
				}
				ASSERT_TRUE(a && b) << what;
				// Without noise nothing else is there. With 5 cm, now and then
				// the returns at the corner happen to line up (a 90 deg V of
				// 8 returns 0.1 m apart, flattened by 2-3 std of noise) and
				// make a short segment of their own: counted below.
				if (noise == 0)
					EXPECT_EQ(others, 0u) << what;
				else
					extra += others;
				// One connected profile (with noise a cluster is now and then
				// cut right at the corner; the segments still meet there).
				if (noise == 0)
				{
					EXPECT_EQ(a->cluster, b->cluster) << what;
				}
				EXPECT_NEAR(std::acos(std::abs(a->direction().dot(b->direction()))), M_PI_2, 5 * kDeg) << what;
				// a ends and b starts at the corner, in scan order.
				Eigen::Matrix2d m;
				m.row(0) = a->normal.transpose();
				m.row(1) = b->normal.transpose();
				const Eigen::Vector2d x = m.inverse() * Eigen::Vector2d(a->offset, b->offset);
				const double e = (x - corner).norm();
				if (noise == 0)
					EXPECT_LE(e, 0.03) << what;
				else
				{
					sumSq += e * e;
					worst = std::max(worst, e);
					count++;
				}
				// The segments end at the corner, to within the resolution of
				// their last points: a beam spacing, two if the ray nearest
				// the corner hit within a hair of both faces and went to the
				// other one. With noise a return within 3 std of both lines
				// may go to either: for these right-angled corners seen at
				// 45 deg, those up to 3 std x sqrt(2) along the wall.
				if (others == 0)
				{
					const double slack = 3 * noise * M_SQRT2 + 1e-6;
					EXPECT_LE((a->end - corner).norm(), 2 * runs[r].spacingEnd + slack) << what;
					EXPECT_LE((b->start - corner).norm(), 2 * runs[r + 1].spacingStart + slack) << what;
				}
			}
		// With 5 cm noise the corner is only as good as the two lines near
		// it (1-2 cm std each): 3 cm RMS over 20 scans, and no single scan
		// grossly off (10 cm: 4-5 std).
		const double rms = std::sqrt(sumSq / static_cast<double>(count));
		std::cout << "[ " << c.name << " ] 5 cm noise: corner error RMS " << 100 * rms
				  << " cm, worst " << 100 * worst << " cm over " << count << " scans; "
				  << extra << " short extra segments at the corner" << std::endl;
		EXPECT_LE(rms, 0.03) << c.name;
		EXPECT_LE(worst, 0.10) << c.name;
		EXPECT_LE(extra, count / 10) << c.name;
		RecordProperty(std::string(c.key) + "_corner_rms_error_m", std::to_string(rms));
		RecordProperty(std::string(c.key) + "_corner_worst_error_m", std::to_string(worst));
	}
}

TEST(ScanLineExtractor, PointsFitAndEndpointsAreConsistent)
{
	// Every segment's own numbers agree with its points: normal unit and
	// towards the sensor, endpoints on the line and in scan order, RMS
	// recomputed from the scan points of its ray range. A range may hold a
	// stray return that is not the segment's (an outlier): the segment's
	// points are then its pointCount points nearest the line.
	const ScanLineExtractor extractor;
	size_t checked = 0;
	for (const auto& pose : kRoomPoses)
		for (double noise : {0.0, 0.05})
		{
			const Scene scene(kRoom, pose);
			const auto scan = scene.scan(noise, 3);
			const auto pts = lvf::lines::scanPoints(*scan);
			const auto segments = extractor.extract(*scan);
			ASSERT_FALSE(segments.empty());
			for (size_t k = 0; k < segments.size(); k++)
			{
				const auto& s = segments[k];
				EXPECT_NEAR(s.normal.norm(), 1.0, 1e-12);
				EXPECT_GT(s.signedDistance(pts.origin), 0);
				EXPECT_NEAR(s.signedDistance(s.start), 0, 1e-9);
				EXPECT_NEAR(s.signedDistance(s.end), 0, 1e-9);
				EXPECT_NEAR(s.direction().dot(s.normal), 0, 1e-9);
				EXPECT_LE(s.firstIndex, s.lastIndex);
				if (k > 0)
				{
					EXPECT_GT(s.firstIndex, segments[k - 1].lastIndex);
					EXPECT_GE(s.cluster, segments[k - 1].cluster);
				}
				std::vector<double> d;
				for (size_t i = 0; i < pts.size(); i++)
					if (pts.ray[i] >= s.firstIndex && pts.ray[i] <= s.lastIndex)
						d.push_back(std::abs(s.signedDistance(pts.xy[i])));
				ASSERT_GE(d.size(), s.pointCount);
				EXPECT_LE(d.size(), s.pointCount + 2) << "more than 2 outliers inside a segment";
				std::sort(d.begin(), d.end());
				double sumSq = 0;
				for (size_t i = 0; i < s.pointCount; i++) sumSq += d[i] * d[i];
				// (1 um: the fit works from sums of squared coordinates.)
				EXPECT_NEAR(std::sqrt(sumSq / s.pointCount), s.rmsResidual, 1e-6);
				EXPECT_GE(s.pointCount, static_cast<size_t>(extractor.options().minPoints));
				EXPECT_GE(s.length(), extractor.options().minLength);
				// The first and last rays are the segment's own points.
				const auto first = std::find(pts.ray.begin(), pts.ray.end(), s.firstIndex);
				const auto last = std::find(pts.ray.begin(), pts.ray.end(), s.lastIndex);
				ASSERT_NE(first, pts.ray.end());
				ASSERT_NE(last, pts.ray.end());
				const auto& p0 = pts.xy[static_cast<size_t>(first - pts.ray.begin())];
				const auto& p1 = pts.xy[static_cast<size_t>(last - pts.ray.begin())];
				EXPECT_NEAR((p0 - s.signedDistance(p0) * s.normal - s.start).norm(), 0, 1e-9);
				EXPECT_NEAR((p1 - s.signedDistance(p1) * s.normal - s.end).norm(), 0, 1e-9);
				checked++;
			}
		}
	EXPECT_GT(checked, 50u);
}
