// lvf-import-middlebury on the real Middlebury 2014 scenes of ../shared/data
// (skipped when they are absent). The scenes that show a floor become rawlogs
// MRPT's tools read; their floor, camera pose, laser and truth scans are
// checked against the ground-truth disparity, read here by hand and placed
// with the rawlog's own calibration and camera pose, i.e. independently of
// the importer's code. Pipes (no floor in view) and every bad file or option
// is one line, exit status 2 and nothing written. lvf-fuse runs on the
// imports without falling back to the laser, and its scores are guarded.

#include "CliTestSupport.h"

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/metrics/TruthScanFile.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/vision/pinhole.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

using namespace lvf::test;

namespace
{
const fs::path kScenes = fs::path(LVF_SHARED_DATA_DIR) / "middlebury";
/** The scenes whose lower image half shows a floor (measured: the others'
 * best near-level planes are table tops or clutter, see FloorFit.h). */
const std::vector<std::string> kFloorScenes{"Motorcycle", "Recycle"};
constexpr double kLaserHeight = 0.30, kSliceHalfWidth = 0.01, kMaxRange = 8.0;	// importer defaults
constexpr double kInlierBand = 0.02;  // FloorFitOptions::inlierBand
const lvf::HeightBand kBand{0.05, 1.20};

/** disp0GT.pfm by hand: "Pf", width, height, scale (< 0: little-endian),
 * one whitespace byte, then float rows from the bottom of the picture up. */
cv::Mat1f readDisparity(const fs::path& path)
{
	std::ifstream in(path, std::ios::binary);
	std::string magic;
	int w = 0, h = 0;
	double scale = 0;
	in >> magic >> w >> h >> scale;
	in.get();
	EXPECT_EQ(magic, "Pf");
	EXPECT_LT(scale, 0) << "this reader (and the test machine) are little-endian";
	cv::Mat1f d(h, w);
	for (int v = h - 1; v >= 0; v--) in.read(reinterpret_cast<char*>(d.ptr<float>(v)), long(w) * 4);
	EXPECT_TRUE(in) << path;
	return d;
}

/** The numbers of calib.txt line `key=...`, read loosely. */
std::vector<double> calibNumbers(const fs::path& calib, const std::string& key)
{
	std::ifstream in(calib);
	for (std::string line; std::getline(in, line);)
	{
		const auto eq = line.find('=');
		if (eq == std::string::npos || line.substr(0, eq).find(key) == std::string::npos) continue;
		std::string values = line.substr(eq + 1);
		for (auto& c : values)
			if (c == '[' || c == ']' || c == ';') c = ' ';
		std::istringstream s(values);
		std::vector<double> out;
		for (double x; s >> x;) out.push_back(x);
		return out;
	}
	return {};
}

struct Rawlog
{
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::obs::CObservationStereoImages::Ptr stereo;
};

Rawlog readRawlog(const fs::path& path)
{
	Rawlog r;
	mrpt::io::CFileGZInputStream file(path.string());
	auto archive = mrpt::serialization::archiveFrom(file);
	for (;;)
	{
		mrpt::serialization::CSerializable::Ptr o;
		try
		{
			o = archive.ReadObject();
		}
		catch (const mrpt::serialization::CExceptionEOF&)
		{
			break;
		}
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) r.scan = s;
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o)) r.stereo = s;
	}
	return r;
}

/** What the importer says on stdout. */
struct Summary
{
	size_t floorInliers = 0, floorCandidates = 0, validRays = 0, rays = 0, hidden = 0, inView = 0;
	double rmsMm = 0, medianMm = 0, cameraHeight = 0, tiltDeg = 0;
};

Summary parseSummary(const std::string& out)
{
	Summary s;
	std::smatch m;
	const std::regex floor(
		R"(floor: (\d+) of (\d+) points .* RMS ([\d.]+) mm \(median ([\d.]+) mm\); camera ([\d.]+) m above it, tilted (-?[\d.]+) deg down)");
	const std::regex laser(R"(laser at [\d.]+ m: (\d+) of (\d+) rays valid)");
	const std::regex hidden(R"(hidden bearings \(.*\): (\d+) of (\d+) in view)");
	EXPECT_TRUE(std::regex_search(out, m, floor)) << out;
	if (m.size() == 7)
	{
		s.floorInliers = std::stoul(m[1]), s.floorCandidates = std::stoul(m[2]);
		s.rmsMm = std::stod(m[3]), s.medianMm = std::stod(m[4]);
		s.cameraHeight = std::stod(m[5]), s.tiltDeg = std::stod(m[6]);
	}
	EXPECT_TRUE(std::regex_search(out, m, laser)) << out;
	if (m.size() == 3) s.validRays = std::stoul(m[1]), s.rays = std::stoul(m[2]);
	EXPECT_TRUE(std::regex_search(out, m, hidden)) << out;
	if (m.size() == 3) s.hidden = std::stoul(m[1]), s.inView = std::stoul(m[2]);
	return s;
}

/** A ground-truth pixel placed in the robot frame with the rawlog's
 * calibration (doffs = cx1 - cx0, baseline = the right camera's x) and the
 * rawlog's camera pose: what lvf-fuse will take the scene to be. */
struct RobotPoint
{
	int u, v;
	double depth;  //!< camera z [m]
	mrpt::math::TPoint3D p;
};

std::vector<RobotPoint> groundTruthInRobotFrame(const fs::path& scene, const mrpt::obs::CObservationStereoImages& st)
{
	const cv::Mat1f disparity = readDisparity(scene / "disp0GT.pfm");
	const cv::Mat mask = cv::imread((scene / "mask0nocc.png").string(), cv::IMREAD_GRAYSCALE);
	const double f = st.leftCamera.fx(), cx = st.leftCamera.cx(), cy = st.leftCamera.cy();
	const double doffs = st.rightCamera.cx() - cx, baseline = st.rightCameraPose.x();
	const mrpt::poses::CPose3D camera(st.cameraPose);
	std::vector<RobotPoint> out;
	for (int v = 0; v < disparity.rows; v++)
		for (int u = 0; u < disparity.cols; u++)
		{
			const float d = disparity(v, u);
			if (!std::isfinite(d) || mask.at<uint8_t>(v, u) == 0) continue;	// unknown: not ground truth
			const double z = baseline * f / (d + doffs);
			out.push_back({u, v, z, camera.composePoint({(u - cx) * z / f, (v - cy) * z / f, z})});
		}
	return out;
}

/** Per ray of `scan`, the nearest horizontal range of the points `keep`
 * accepts (inf: none), and which point it was; bearings binned to the
 * nearest ray, as a scanner's beams tile its aperture. */
template <typename Keep>
std::vector<std::pair<float, const RobotPoint*>> nearestPerRay(
	const std::vector<RobotPoint>& points, const mrpt::obs::CObservation2DRangeScan& scan, Keep&& keep)
{
	const size_t n = scan.getScanSize();
	const double step = scan.aperture / double(n - 1);
	std::vector<std::pair<float, const RobotPoint*>> best(n, {std::numeric_limits<float>::infinity(), nullptr});
	for (const auto& g : points)
	{
		if (!keep(g)) continue;
		const long i = std::lround((std::atan2(g.p.y, g.p.x) + 0.5 * scan.aperture) / step);
		if (i < 0 || i >= long(n)) continue;
		const auto r = static_cast<float>(std::hypot(g.p.x, g.p.y));
		if (r < best[size_t(i)].first) best[size_t(i)] = {r, &g};
	}
	return best;
}

class MiddleburyImport : public CliTest
{
   protected:
	void SetUp() override
	{
		CliTest::SetUp();
		if (!fs::is_directory(kScenes))
			GTEST_SKIP() << kScenes << " is absent: the Middlebury scenes are not part of the project "
						 << "(see ../shared/data/README.md); nothing to import";
	}

	RunResult import(const std::string& args) const { return run(LVF_IMPORT_MIDDLEBURY_BIN, args); }

	/** A scene folder in the test's own folder whose files link to
	 * Motorcycle's, except those `spoil` writes itself. */
	template <typename Spoil>
	fs::path spoiltScene(const std::string& name, Spoil&& spoil) const
	{
		const fs::path dir = m_dir / name;
		fs::create_directories(dir);
		for (const char* f : {"calib.txt", "im0.png", "im1.png", "disp0GT.pfm", "mask0nocc.png"})
			fs::create_symlink(kScenes / "Motorcycle" / f, dir / f);
		spoil(dir);
		return dir;
	}
};

/** The tests that fuse the imported scenes: lvf-fuse is a dependency of
 * this test target, so its absence is a failure, not a skip. */
class MiddleburyFusion : public MiddleburyImport
{
   protected:
	void SetUp() override
	{
		MiddleburyImport::SetUp();
		if (IsSkipped()) return;
		ASSERT_TRUE(fs::exists(LVF_FUSE_BIN)) << LVF_FUSE_BIN << " is not built (a dependency of this test)";
	}

	/** `scene` imported, then fused with the INI text `ini` (first) and as
	 * shipped (second): lvf-fuse's two runs, for their summaries. */
	std::pair<RunResult, RunResult> fuseWithIniAndAsShipped(const std::string& scene, const std::string& ini) const
	{
		const auto imported = import("--scene " + (kScenes / scene).string() + " --out in -q");
		EXPECT_EQ(imported.status, 0) << imported.err;
		std::ofstream(m_dir / "variant.ini") << ini;
		auto variant = run(LVF_FUSE_BIN, "--input in/" + scene + ".rawlog --outdir a --config variant.ini");
		auto shipped = run(LVF_FUSE_BIN, "--input in/" + scene + ".rawlog --outdir b");
		EXPECT_EQ(variant.status, 0) << variant.err;
		EXPECT_EQ(shipped.status, 0) << shipped.err;
		return {variant, shipped};
	}
};

/** Replaces `dir/file` (a link) by the given text. */
void replaceFile(const fs::path& dir, const std::string& file, const std::string& text)
{
	fs::remove(dir / file);
	std::ofstream(dir / file, std::ios::binary) << text;
}

}  // namespace

TEST_F(MiddleburyImport, FloorScenesBecomeRawlogsWhoseLaserAndTruthMatchTheGroundTruth)
{
	for (const auto& name : kFloorScenes)
	{
		SCOPED_TRACE(name);
		const fs::path scene = kScenes / name, out = m_dir / "out";
		const auto r = import("--scene " + scene.string() + " --out out");
		ASSERT_EQ(r.status, 0) << r.err;
		EXPECT_EQ(r.err, "");
		std::cout << r.out;
		for (const auto& f : {name + ".rawlog", name + "_truth_scans.csv", name + "_gt_poses.txt"})
			EXPECT_TRUE(fs::exists(out / f)) << f;
		for (const auto& e : fs::directory_iterator(m_dir))
			EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos);
		const Summary said = parseSummary(r.out);

		// MRPT's own tool reads it: one laser scan, one stereo pair.
		const auto info = run(LVF_RAWLOG_EDIT, "--info -i " + (out / (name + ".rawlog")).string());
		ASSERT_EQ(info.status, 0) << info.err;
		const auto counts = labelCounts(info.out);
		EXPECT_EQ(counts.at("LASER"), 1);
		EXPECT_EQ(counts.at("STEREO"), 1);
		const Rawlog log = readRawlog(out / (name + ".rawlog"));
		ASSERT_TRUE(log.scan && log.stereo);
		const auto& scan = *log.scan;
		const auto& st = *log.stereo;

		// The calibration is calib.txt's: f, both cx, cy; baseline mm -> m,
		// the right camera a pure translation along the left one's x.
		const fs::path calib = scene / "calib.txt";
		const auto cam0 = calibNumbers(calib, "cam0"), cam1 = calibNumbers(calib, "cam1");
		const auto width = calibNumbers(calib, "width"), height = calibNumbers(calib, "height");
		ASSERT_EQ(cam0.size(), 9u);
		ASSERT_EQ(cam1.size(), 9u);
		ASSERT_EQ(width.size(), 1u);
		ASSERT_EQ(height.size(), 1u);
		EXPECT_DOUBLE_EQ(st.leftCamera.fx(), cam0[0]);
		EXPECT_DOUBLE_EQ(st.leftCamera.cx(), cam0[2]);
		EXPECT_DOUBLE_EQ(st.leftCamera.cy(), cam0[5]);
		EXPECT_DOUBLE_EQ(st.rightCamera.cx(), cam1[2]);
		EXPECT_EQ(st.leftCamera.ncols, uint32_t(width[0]));
		EXPECT_EQ(st.leftCamera.nrows, uint32_t(height[0]));
		EXPECT_EQ(st.imageLeft.getWidth(), st.leftCamera.ncols);
		EXPECT_EQ(st.imageRight.getHeight(), st.leftCamera.nrows);
		EXPECT_TRUE(st.hasImageRight);
		EXPECT_NEAR(st.rightCameraPose.x(), calibNumbers(calib, "baseline").at(0) / 1000, 1e-9);
		EXPECT_NEAR(mrpt::poses::CPose3D(st.rightCameraPose).norm(), st.rightCameraPose.x(), 1e-9);
		EXPECT_NEAR(st.rightCameraPose.quat().r(), 1.0, 1e-12) << "rectified: no rotation";

		// The floor, as the rawlog's camera pose puts it at z = 0: the
		// ground-truth points of the lower image half within the fit's
		// +-2 cm band. Bound: RMS < 1 cm, the laser slice's half-width --
		// were the floor known worse than that, "0.30 m above the floor"
		// would not say which slice the laser sees. (Measured: Motorcycle
		// 3.4 mm, Recycle 5.8 mm with the cloth lying on its floor; the
		// median residual, 2.1 and 2.4 mm, is the floors' own scatter.)
		const auto gt = groundTruthInRobotFrame(scene, st);
		size_t lower = 0, inliers = 0;
		double sumSq = 0;
		for (const auto& g : gt)
		{
			if (g.v <= st.leftCamera.cy()) continue;
			lower++;
			if (std::abs(g.p.z) > kInlierBand) continue;
			inliers++;
			sumSq += g.p.z * g.p.z;
		}
		const double rms = std::sqrt(sumSq / double(std::max<size_t>(inliers, 1)));
		EXPECT_LT(rms, kSliceHalfWidth);
		EXPECT_NEAR(1000 * rms, said.rmsMm, 0.051) << "the summary reports the floor the rawlog holds";
		EXPECT_NEAR(double(inliers), double(said.floorInliers), 0.001 * double(inliers));
		EXPECT_EQ(lower, said.floorCandidates);
		EXPECT_GT(double(inliers), 0.10 * double(lower)) << "a floor fills much of the lower image";

		// The camera: Middlebury's rig stood on a tripod, chest-high, looking
		// somewhat down -- 0.5 to 2 m above the floor, 0 to 45 deg down.
		const mrpt::poses::CPose3D camera(st.cameraPose);
		EXPECT_GT(camera.z(), 0.5);
		EXPECT_LT(camera.z(), 2.0);
		EXPECT_NEAR(camera.z(), said.cameraHeight, 0.0005);
		EXPECT_NEAR(camera.x(), 0, 1e-9) << "the robot origin is below the camera";
		EXPECT_NEAR(camera.y(), 0, 1e-9);
		const auto R = camera.getRotationMatrix();	// columns: camera axes in the robot frame
		const double tiltDeg = mrpt::RAD2DEG(std::asin(-R(2, 2)));
		EXPECT_GT(tiltDeg, 0);
		EXPECT_LT(tiltDeg, 45);
		EXPECT_NEAR(tiltDeg, said.tiltDeg, 0.051);
		EXPECT_NEAR(R(1, 2), 0, 1e-9) << "robot x is the optical axis projected on the floor";
		EXPECT_GT(R(0, 2), 0);

		// The laser: at the robot origin, 0.30 m up, facing x; per ray the
		// nearest ground-truth point within +-1 cm of that height and 8 m.
		EXPECT_EQ(scan.sensorLabel, "LASER");
		EXPECT_NEAR(scan.sensorPose.distanceTo(mrpt::poses::CPose3D(0, 0, kLaserHeight, 0, 0, 0)), 0, 1e-9);
		EXPECT_NEAR(std::abs(scan.sensorPose.yaw()) + std::abs(scan.sensorPose.pitch()) + std::abs(scan.sensorPose.roll()), 0, 1e-9);
		EXPECT_TRUE(scan.rightToLeft);
		EXPECT_FLOAT_EQ(scan.maxRange, float(kMaxRange));
		EXPECT_NEAR(scan.aperture / double(scan.getScanSize() - 1), mrpt::DEG2RAD(0.5), 1e-6);
		EXPECT_EQ(scan.getScanSize(), said.rays);
		const auto laser = nearestPerRay(gt, scan, [](const RobotPoint& g) {
			return std::abs(g.p.z - kLaserHeight) <= kSliceHalfWidth && std::hypot(g.p.x, g.p.y) <= kMaxRange;
		});
		const double step = scan.aperture / double(scan.getScanSize() - 1);
		size_t valid = 0;
		for (size_t i = 0; i < scan.getScanSize(); i++)
		{
			ASSERT_EQ(scan.getScanRangeValidity(i), laser[i].second != nullptr) << "ray " << i;
			if (!laser[i].second) continue;
			valid++;
			EXPECT_NEAR(scan.getScanRange(i), laser[i].first, 1e-4) << "ray " << i;
			// The pixel it came from lies where the rawlog's calibration
			// projects the ray's end, within the ray's width (half a step
			// either side) and the slice's (+-1 cm), plus a pixel for
			// rounding; and the camera depth there is the ground truth's.
			const double b = scan.getScanAngle(i), range = scan.getScanRange(i);
			double uMin = 1e9, uMax = -1e9, vMin = 1e9, vMax = -1e9;
			for (const double db : {-0.5 * step, 0.5 * step})
				for (const double dh : {-kSliceHalfWidth, kSliceHalfWidth})
				{
					const auto c = camera.inverseComposePoint(
						{range * std::cos(b + db), range * std::sin(b + db), kLaserHeight + dh});
					mrpt::img::TPixelCoordf px;
					mrpt::vision::pinhole::projectPoint_with_distortion(c, st.leftCamera, px);
					uMin = std::min<double>(uMin, px.x), uMax = std::max<double>(uMax, px.x);
					vMin = std::min<double>(vMin, px.y), vMax = std::max<double>(vMax, px.y);
				}
			const auto& src = *laser[i].second;
			EXPECT_TRUE(src.u >= uMin - 1 && src.u <= uMax + 1) << "ray " << i << ": u " << src.u << " not in [" << uMin << ", " << uMax << "]";
			EXPECT_TRUE(src.v >= vMin - 1 && src.v <= vMax + 1) << "ray " << i << ": v " << src.v << " not in [" << vMin << ", " << vMax << "]";
			const auto end = camera.inverseComposePoint({range * std::cos(b), range * std::sin(b), kLaserHeight});
			EXPECT_NEAR(end.z, src.depth, range * std::tan(0.5 * step) + kSliceHalfWidth) << "ray " << i;
		}
		EXPECT_EQ(valid, said.validRays);
		EXPECT_GT(valid, scan.getScanSize() / 2) << "the laser slice hits something on most bearings";

		// The truth scan: the format lvf-simulate writes, one range per ray,
		// each the nearest ground-truth point in the robot height band.
		const auto truthFile = lvf::metrics::readTruthScans((out / (name + "_truth_scans.csv")).string());
		ASSERT_EQ(truthFile.size(), 1u);
		const auto* truth = lvf::metrics::findTruthScan(truthFile, mrpt::Clock::toDouble(scan.timestamp));
		ASSERT_NE(truth, nullptr);
		ASSERT_EQ(truth->ranges.size(), scan.getScanSize());
		const auto band = nearestPerRay(gt, scan, [](const RobotPoint& g) { return kBand.contains(g.p.z); });
		for (size_t i = 0; i < scan.getScanSize(); i++)
		{
			if (!band[i].second)
				EXPECT_TRUE(std::isinf(truth->ranges[i])) << "ray " << i;
			else
				EXPECT_NEAR(truth->ranges[i], band[i].first, 1e-4 + 1e-6) << "ray " << i;
		}
		EXPECT_EQ(
			slurp(out / (name + "_gt_poses.txt")),
			"# ground-truth robot poses: frame timestamp[s] x[m] y[m] yaw[rad]\n"
			"0 1700000000.000000 0.000000 0.000000 0.000000\n");

		// Hidden bearings: what these scenes are for (a motorcycle seat, a
		// bin lid above the laser's slice) -- the vision must find them.
		const auto inView = lvf::metrics::bearingsInView(scan, truth->ranges, st, kBand, kMaxRange);
		const auto hidden = lvf::metrics::hiddenBearings(scan, truth->ranges, inView);
		EXPECT_EQ(size_t(std::count(hidden.begin(), hidden.end(), true)), said.hidden);
		EXPECT_EQ(size_t(std::count(inView.begin(), inView.end(), true)), said.inView);
		EXPECT_GT(said.hidden, 0u);
		fs::remove_all(out);
	}
}

TEST_F(MiddleburyImport, PipesShowsNoFloorAndIsRefused)
{
	// Pipes' lower half is pipes, a brick wall and a tank: its best near-level
	// plane holds ~5% of the points, spread through the band like clutter.
	const auto r = import("--scene " + (kScenes / "Pipes").string() + " --out out");
	EXPECT_EQ(r.status, 2) << r.out << r.err;
	EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
	EXPECT_EQ(r.err.rfind("lvf-import-middlebury: error: " + (kScenes / "Pipes/disp0GT.pfm").string() +
						  ": no floor visible: ",
						  0),
			  0u)
		<< r.err;
	EXPECT_FALSE(fs::exists(m_dir / "out"));
}

TEST_F(MiddleburyImport, EveryBadSceneOrOptionIsOneLineExitTwoAndNothingWritten)
{
	const std::string calib = slurp(kScenes / "Motorcycle/calib.txt");
	auto without = [&](const std::string& key) {
		std::istringstream in(calib);
		std::string kept;
		for (std::string l; std::getline(in, l);)
			if (l.find(key) == std::string::npos) kept += l + "\n";
		return kept;
	};
	const std::string pfm = slurp(kScenes / "Motorcycle/disp0GT.pfm");
	const auto noBaseline = spoiltScene("NoBaseline", [&](const fs::path& d) { replaceFile(d, "calib.txt", without("baseline")); });
	const auto badDoffs = spoiltScene("BadDoffs", [&](const fs::path& d) {
		replaceFile(d, "calib.txt", without("doffs") + "doffs= 3x\n");
	});
	const auto badCam = spoiltScene("BadCam", [&](const fs::path& d) {
		replaceFile(d, "calib.txt", without("cam1") + "cam1=[ 999.421 0 326.96 ; 0 999.421 252.932 ]\n");
	});
	const auto wrongWidth = spoiltScene("WrongWidth", [&](const fs::path& d) {
		replaceFile(d, "calib.txt", without("width") + "width= 740\n");
	});
	const auto truncated = spoiltScene("Truncated", [&](const fs::path& d) { replaceFile(d, "disp0GT.pfm", pfm.substr(0, 100000)); });
	const auto colourPfm = spoiltScene("ColourPfm", [&](const fs::path& d) { replaceFile(d, "disp0GT.pfm", "PF" + pfm.substr(2)); });
	const auto noMask = spoiltScene("NoMask", [&](const fs::path& d) { fs::remove(d / "mask0nocc.png"); });
	const std::string good = "--scene " + (kScenes / "Motorcycle").string();

	const std::vector<std::pair<std::string, std::string>> cases{
		{"--scene " + (m_dir / "NoSuchScene").string(), "NoSuchScene: scene folder not found"},
		{"--scene " + noMask.string(), "NoMask/mask0nocc.png: file not found"},
		{"--scene " + (kScenes / "Motorcycle" / "calib.txt").string(), "calib.txt: is a file, not a scene folder"},
		{"--scene " + noBaseline.string(), "NoBaseline/calib.txt: baseline: missing field"},
		{"--scene " + badDoffs.string(), "BadDoffs/calib.txt: line 12: doffs: '3x' is not a number"},
		{"--scene " + badCam.string(), "BadCam/calib.txt: line 12: cam1: '[ 999.421 0 326.96 ; 0 999.421 252.932 ]' is not a 3x3 matrix (6 numbers)"},
		{"--scene " + wrongWidth.string(), "WrongWidth/im0.png: 741x497 pixels, but calib.txt says width 740, height 497"},
		{"--scene " + truncated.string(),
		 "Truncated/disp0GT.pfm: pixel data: 99979 of 1473108 bytes (741x497 floats): file truncated"},
		{"--scene " + colourPfm.string(), "ColourPfm/disp0GT.pfm: header: type: colour PFM (PF), expected one channel (Pf)"},
		{good + " --laser-height 0", "--laser-height: must be > 0"},
		{good + " --laser-height 5", "--laser-height: must be below --robot-height"},
		{good + " --robot-height 0.01", "--robot-height: must be above --obstacle-min-height"},
		{good + " --max-range -1", "--max-range: must be > 0"},
		{good + " --resolution-deg 0", "--resolution-deg: must be in (0, 10]"},
		{good + " --fov-deg 0.1", "--fov-deg: must be in [--resolution-deg, 360]"},
		{good + " --laser-height low", "command line"},
	};
	for (const auto& [args, expected] : cases)
	{
		const auto r = import(args + " --out out");
		EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
		EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
		EXPECT_EQ(r.err.rfind("lvf-import-middlebury: error: ", 0), 0u) << r.err;
		EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
		EXPECT_FALSE(fs::exists(m_dir / "out")) << args;
	}
	const auto noOut = import(good);
	EXPECT_EQ(noOut.status, 2);
	EXPECT_NE(noOut.err.find("command line: missing required argument(s) --out or --outdir (see --help)"), std::string::npos) << noOut.err;
	// --outdir, as the other programs name it, does the same as --out.
	const auto viaOutdir = import(good + " --outdir other -q");
	EXPECT_EQ(viaOutdir.status, 0) << viaOutdir.err;
	EXPECT_TRUE(fs::exists(m_dir / "other" / "Motorcycle.rawlog"));
}

/** "recall 0.348 of 23 hidden bearings, phantom rate 0.1310 of 84 in view" */
std::pair<double, double> recallAndPhantomRate(const std::string& summary)
{
	const auto r = summary.find("recall "), p = summary.find("phantom rate ");
	if (r == std::string::npos || p == std::string::npos) return {-1, -1};
	return {std::stod(summary.substr(r + 7)), std::stod(summary.substr(p + 13))};
}

TEST_F(MiddleburyFusion, LvfFuseFindsHiddenObstaclesInTheRealScenes)
{
	// Issue #3's targets on these scenes: recall >= 0.8 and phantom rate
	// <= 0.05. Measured: Motorcycle 0.826 / 0, Recycle 0.906 / 0.027; the
	// range taken also from the points near each bearing (ScanFusion.h,
	// central_share) took them from 0.739 and 0.868. Motorcycle's misses:
	// returns at the image's edge (no right view), and the nearest part of
	// the front wheel, which does not match; Recycle's: the bins' bases,
	// 5-10 cm above the floor, untextured, a lid's rim, the image's edges.
	// (Recycle: 0.434 with texture gates fixed at 4 and 5 grey levels, where
	// relative to the image's noise they are ~1 on these clean images,
	// ImageNoise.h. Motorcycle: 0.217 while the line extractor used the
	// thresholds for 5 cm of range noise on this 1 cm slice: one segment
	// through the whole motorcycle, test_line_segments'
	// ThresholdsFollowTheScansStatedNoise.)
	const std::map<std::string, std::pair<double, double>> floor{{"Motorcycle", {0.80, 0.05}}, {"Recycle", {0.80, 0.05}}};
	for (const auto& name : kFloorScenes)
	{
		SCOPED_TRACE(name);
		const auto imported = import("--scene " + (kScenes / name).string() + " --out in -q");
		ASSERT_EQ(imported.status, 0) << imported.err;
		const auto fused = run(LVF_FUSE_BIN, "--input in/" + name + ".rawlog --outdir fused");
		ASSERT_EQ(fused.status, 0) << fused.err;
		// A cluttered real scene contradicts a floor-and-walls model over most
		// of the image; that must not pass for a wrong calibration.
		EXPECT_EQ(fused.err, "") << "no warning, no fall-back to the laser";
		const auto [recall, phantomRate] = recallAndPhantomRate(fused.out);
		std::cout << "[ lvf-fuse ] " << name << ": recall " << recall << ", phantom rate " << phantomRate << "\n";
		EXPECT_GE(recall, floor.at(name).first) << fused.out;
		EXPECT_LE(phantomRate, floor.at(name).second) << fused.out;
		EXPECT_GE(phantomRate, 0) << fused.out;
	}
}

TEST_F(MiddleburyFusion, FloorDisparityMarginFindsTheBinsBases)
{
	// Recycle's bins stand on the floor; their bases, 5-10 cm up, are in
	// the band but within d_allow (0.12 m of depth, ~7 px of disparity in
	// these images) of the floor model, so criterion a hides them. With
	// floor_disparity_margin = 2 (px, the default) it spares them. Measured: recall
	// 0.755 -> 0.906, phantom rate 0 -> 0.036 (4 bearings of 112: a base
	// found 0.14 m too near, and the gaps either side of it closed onto it;
	// 3 with bins as narrow as the scan's 0.5-degree rays, before
	// ScanFusion's bin_width_deg; those 4 are floor points 5-6 cm "up",
	// which visual_floor_clearance now keeps out, below); bounded by the
	// issue's target, 0.05;
	// with the range from the three points nearest each bearing only
	// (central_share 0) 0.717 -> 0.868, the same phantoms; before gaps were
	// closed (NarrowGapBridging.h), 0.585 -> 0.698, 0 -> 0.009.
	const auto [paper, narrowed] =
		fuseWithIniAndAsShipped("Recycle", "[FocusedEpipolarSearch]\nfloor_disparity_margin = 0\n");
	const auto [before, phantomsBefore] = recallAndPhantomRate(paper.out);
	const auto [after, phantomsAfter] = recallAndPhantomRate(narrowed.out);
	std::cout << "[ lvf-fuse ] Recycle: recall " << before << " -> " << after << ", phantom rate "
			  << phantomsBefore << " -> " << phantomsAfter << "\n";
	EXPECT_GE(after, before + 0.08) << narrowed.out;
	EXPECT_GE(after, 0.84) << narrowed.out;
	EXPECT_LE(phantomsAfter, 0.05) << narrowed.out;
}

TEST_F(MiddleburyFusion, VisualFloorClearanceKeepsTheFloorBeforeTheBinsOutOfTheScan)
{
	// In front of Recycle's leftmost bin the search, spared by
	// floor_disparity_margin, matches the floor itself and triangulates it
	// 0.051-0.063 m up: just inside the band, and four bearings came out
	// 0.12-0.14 m nearer than the truth. A visual point must clear the
	// band's lower edge by visual_floor_clearance (1 cm): measured, phantom
	// rate 0.036 -> 0, recall 0.906 both.
	const auto [without, with] =
		fuseWithIniAndAsShipped("Recycle", "[CLaserStereoFusion]\nvisual_floor_clearance = 0\n");
	const auto [recallWithout, phantomsWithout] = recallAndPhantomRate(without.out);
	const auto [recallWith, phantomsWith] = recallAndPhantomRate(with.out);
	std::cout << "[ lvf-fuse ] Recycle, visual_floor_clearance 0 -> 0.01: recall " << recallWithout << " -> "
			  << recallWith << ", phantom rate " << phantomsWithout << " -> " << phantomsWith << "\n";
	EXPECT_GT(phantomsWithout, 0.02) << "the scene no longer shows the floor matched in front of the bins";
	EXPECT_LT(phantomsWith, phantomsWithout - 0.02) << with.out;
	EXPECT_GE(recallWith, recallWithout) << with.out;
}

TEST_F(MiddleburyFusion, RangesNearTheBearingFindTheMotorcyclesFrontAtEveryLaserHeight)
{
	// The laser slice at other heights sees other parts of the motorcycle,
	// and a hidden obstacle is in other bearings: the fusion's range rule
	// (ScanFusion.h, central_share) must help there too, not just on the
	// slice it was tuned on (0.30 m). Measured, central_share 0 -> 0.15:
	// recall 0.812 -> 0.938 (48 hidden bearings) at 0.15 m, 0.737 -> 0.842
	// (19) at 0.25 m, 0.739 -> 0.826 (23) at 0.30 m, 0.700 both (30) at 0.35
	// m; no phantom in any. Both runs search every grid row (nearest first
	// off), as when the rule was chosen: nearest first leaves fewer points
	// a bearing, and the three nearest the bearing then hold the front more
	// often (central_share 0 with it: 0.875 / 0.789 / 0.826; the shipped
	// fusion's recall is the same either way, checked below). Both without
	// neighbour_bins, which came later and lends bins with few points of
	// their own their neighbours' (central_share 0 with it at 0.30 m: 0.783),
	// and with bins as wide as the scan's 0.5-degree rays, as then
	// (bin_width_deg, later too; with the shipped 1-degree bins central_share
	// 0 -> 0.15 gives 0.833 -> 0.958, 0.789 -> 0.895, 0.826 -> 0.870 at
	// 0.15 / 0.25 / 0.30 m, no phantom).
	const std::string name = "Motorcycle";
	std::ofstream(m_dir / "c0.ini") << "[ScanFusion]\ncentral_share = 0\nneighbour_bins = 0\nbin_width_deg = 0.5\n"
									<< "[FocusedEpipolarSearch]\nnearest_first_levels = 0\n";
	std::ofstream(m_dir / "rows.ini") << "[ScanFusion]\nneighbour_bins = 0\nbin_width_deg = 0.5\n"
									  << "[FocusedEpipolarSearch]\nnearest_first_levels = 0\n";
	for (const std::string height : {"0.15", "0.25", "0.30"})
	{
		SCOPED_TRACE(height);
		const auto imported =
			import("--scene " + (kScenes / name).string() + " --out in" + height + " --laser-height " + height + " -q");
		ASSERT_EQ(imported.status, 0) << imported.err;
		const std::string input = "--input in" + height + "/" + name + ".rawlog --outdir ";
		const auto nearest3 = run(LVF_FUSE_BIN, input + "a" + height + " --config c0.ini");
		const auto rule = run(LVF_FUSE_BIN, input + "b" + height + " --config rows.ini");
		const auto shipped = run(LVF_FUSE_BIN, input + "c" + height);
		ASSERT_EQ(nearest3.status, 0) << nearest3.err;
		ASSERT_EQ(rule.status, 0) << rule.err;
		ASSERT_EQ(shipped.status, 0) << shipped.err;
		const auto [before, phantomsBefore] = recallAndPhantomRate(nearest3.out);
		const auto [after, phantomsAfter] = recallAndPhantomRate(rule.out);
		const auto [now, phantomsNow] = recallAndPhantomRate(shipped.out);
		std::cout << "[ lvf-fuse ] Motorcycle, laser at " << height << " m: recall " << before << " -> " << after
				  << ", phantom rate " << phantomsBefore << " -> " << phantomsAfter << "; shipped " << now << ", "
				  << phantomsNow << "\n";
		EXPECT_GE(after, before + 0.08) << rule.out;
		EXPECT_LE(phantomsAfter, phantomsBefore) << rule.out;
		EXPECT_GE(now, std::max(after, 0.8)) << shipped.out;
		// neighbour_bins costs one bearing of 84 at 0.15 m (1.96 m out
		// where the truth is 2.12 m: two points of its own, a few beside
		// it); the simulated rooms' phantom target bounds it.
		EXPECT_LE(phantomsNow, std::max(phantomsBefore, 0.02)) << shipped.out;
	}
}

TEST_F(MiddleburyFusion, CalibrationCheckKeepsItsOwnNccWhenTheModelCheckIsStricter)
{
	// Recycle's floor agrees with the model at 0.33 of its pixels at NCC 0.9
	// and at 0.17 at 0.95 (measured), against the 0.2 below which a frame is
	// taken for a wrong calibration. A stricter model check (searching more
	// pixels) must not send the scene to the laser alone: the checks keep
	// their own calibration_ncc; set to 0.95 too, they do fall back.
	const std::string name = "Recycle";
	const auto imported = import("--scene " + (kScenes / name).string() + " --out in -q");
	ASSERT_EQ(imported.status, 0) << imported.err;
	std::ofstream(m_dir / "strict_model.ini") << "[ModelEvaluator]\nncc_threshold = 0.95\n";
	std::ofstream(m_dir / "strict_both.ini")
		<< "[CLaserStereoFusion]\ncalibration_ncc = 0.95\n[ModelEvaluator]\nncc_threshold = 0.95\n";
	const auto model = run(LVF_FUSE_BIN, "--input in/" + name + ".rawlog --outdir a --config strict_model.ini");
	ASSERT_EQ(model.status, 0) << model.err;
	EXPECT_EQ(model.err, "") << "no fall-back to the laser";
	EXPECT_GE(recallAndPhantomRate(model.out).first, 0.55) << model.out;
	const auto both = run(LVF_FUSE_BIN, "--input in/" + name + ".rawlog --outdir b --config strict_both.ini");
	ASSERT_EQ(both.status, 0) << both.err;
	EXPECT_NE(both.err.find("calibration suspect"), std::string::npos) << both.err;
}

namespace
{
/** The right image a camera at the same place would have taken turned by
 * `rvec` (Rodrigues, camera axes) and with lens `dist`, and the pair's
 * calibration saying so: a rig lvf-fuse must rectify. Each raw pixel's ray,
 * undistorted and turned into the original camera, is sampled there
 * (OpenCV's undistortPoints with R: X_original = R X_raw). */
void turnRightCamera(mrpt::obs::CObservationStereoImages& stereo, const cv::Vec3d& rvec, const std::vector<double>& dist)
{
	const auto& cam = stereo.rightCamera;
	const cv::Matx33d K(cam.fx(), 0, cam.cx(), 0, cam.fy(), cam.cy(), 0, 0, 1);
	cv::Matx33d R;
	cv::Rodrigues(rvec, R);
	const cv::Mat original = stereo.imageRight.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	std::vector<cv::Point2f> raw, there;
	for (int v = 0; v < original.rows; v++)
		for (int u = 0; u < original.cols; u++) raw.emplace_back(float(u), float(v));
	cv::undistortPoints(raw, there, K, dist, R, K);
	cv::Mat1f mapX(original.size()), mapY(original.size());
	for (size_t k = 0; k < there.size(); k++)
		mapX(int(k) / original.cols, int(k) % original.cols) = there[k].x,
					 mapY(int(k) / original.cols, int(k) % original.cols) = there[k].y;
	cv::Mat turned;
	cv::remap(original, turned, mapX, mapY, cv::INTER_CUBIC);
	stereo.imageRight = mrpt::img::CImage(turned, mrpt::img::DEEP_COPY);
	for (size_t i = 0; i < dist.size(); i++) stereo.rightCamera.dist[i] = dist[i];
	// The right camera in the left one's frame: X_left = R X_raw + t.
	const mrpt::poses::CPose3D right(stereo.rightCameraPose);
	mrpt::math::CMatrixDouble33 turn;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) turn(i, j) = R(i, j);
	mrpt::poses::CPose3D turnedRight(right);
	turnedRight.setRotationMatrix(right.getRotationMatrix() * turn);
	stereo.rightCameraPose = mrpt::poses::CPose3DQuat(turnedRight);
}

void writeObservations(const fs::path& path, const std::vector<mrpt::obs::CObservation::Ptr>& observations)
{
	lvf::common::RawlogWriter out(path.string(), lvf::common::RawlogFormat::Observations);
	for (const auto& o : observations) out.appendEntry(*o);
}
}  // namespace

TEST_F(MiddleburyFusion, ARigThatNeedsRectifyingFusesTheRealScenesAsWell)
{
	// The right camera turned 1 degree and rolled 0.5, with a barrel lens:
	// lvf-fuse rectifies the pair (OpenCV's stereoRectify, RectifiedStereo.h)
	// and must find on these real images what it finds on the rectified
	// pair, at the same ranges. Measured: the visual ranges of the bearings
	// both runs found agree within 2 mm (Motorcycle, 33 bearings) and 8 mm
	// (Recycle, 71) at the median; hidden bearings with a visual range 20
	// and 49 both; recall 0.870 both and 0.906 -> 0.925; phantom rate
	// 0 -> 0.012 and 0.036 -> 0.018. With rectify_alpha 0 (only what both
	// cameras imaged) 20 -> 19 and 49 -> 48 hidden bearings found, recall
	// 0.739 and 0.887: the crop took Motorcycle's right edge.
	for (const auto& name : kFloorScenes)
	{
		SCOPED_TRACE(name);
		const auto imported = import("--scene " + (kScenes / name).string() + " --out in -q");
		ASSERT_EQ(imported.status, 0) << imported.err;
		const Rawlog log = readRawlog(m_dir / "in" / (name + ".rawlog"));
		ASSERT_TRUE(log.scan && log.stereo);
		auto turned = mrpt::obs::CObservationStereoImages::Create(*log.stereo);
		turnRightCamera(*turned, cv::Vec3d(0, mrpt::DEG2RAD(1.0), mrpt::DEG2RAD(0.5)), {-0.1, 0.01, 0, 0, 0});
		writeObservations(m_dir / "as_is.rawlog", {log.scan, log.stereo});
		writeObservations(m_dir / "turned.rawlog", {log.scan, turned});
		const std::string truth = " --truth in/" + name + "_truth_scans.csv";
		const auto asIs = run(LVF_FUSE_BIN, "--input as_is.rawlog --outdir a" + truth);
		const auto rectified = run(LVF_FUSE_BIN, "--input turned.rawlog --outdir b" + truth);
		ASSERT_EQ(asIs.status, 0) << asIs.err;
		ASSERT_EQ(rectified.status, 0) << rectified.err;
		EXPECT_EQ(rectified.err, "") << "no warning, no fall-back to the laser";
		EXPECT_NE(rectified.out.find("the stereo pairs rectified ("), std::string::npos) << rectified.out;
		EXPECT_EQ(asIs.out.find("rectified"), std::string::npos) << "Middlebury's pairs come rectified\n" << asIs.out;

		const auto before = readCsv(m_dir / "a/as_is_bearings.csv"), after = readCsv(m_dir / "b/turned_bearings.csv");
		ASSERT_EQ(before.size(), after.size());
		std::vector<double> differences;
		size_t hiddenFoundBefore = 0, hiddenFoundAfter = 0;
		for (size_t i = 0; i < before.size(); i++)
		{
			const auto &b = before[i], &a = after[i];
			const bool hidden = b.at("hidden") == "1";
			hiddenFoundBefore += hidden && !b.at("visual_m").empty();
			hiddenFoundAfter += hidden && !a.at("visual_m").empty();
			if (b.at("in_view") == "1" && !b.at("visual_m").empty() && !a.at("visual_m").empty())
				differences.push_back(std::abs(std::stod(a.at("visual_m")) - std::stod(b.at("visual_m"))));
		}
		ASSERT_GE(differences.size(), 20u);
		std::nth_element(differences.begin(), differences.begin() + long(differences.size() / 2), differences.end());
		const double median = differences[differences.size() / 2];
		const auto [recallAsIs, phantomsAsIs] = recallAndPhantomRate(asIs.out);
		const auto [recall, phantoms] = recallAndPhantomRate(rectified.out);
		std::cout << "[ lvf-fuse ] " << name << ": visual ranges of " << differences.size()
				  << " bearings, median difference " << median << " m; hidden bearings found " << hiddenFoundBefore
				  << " -> " << hiddenFoundAfter << "; recall " << recallAsIs << " -> " << recall << ", phantom rate "
				  << phantomsAsIs << " -> " << phantoms << "\n";
		EXPECT_LE(median, 0.02);
		EXPECT_GE(hiddenFoundAfter + 2, hiddenFoundBefore);
		EXPECT_LE(phantoms, 0.05) << rectified.out;
	}
}
