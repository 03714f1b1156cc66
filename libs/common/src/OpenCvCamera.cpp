#include <lvfusion/common/OpenCvCamera.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <stdexcept>

namespace lvf::common
{
cv::Matx33d openCvCameraMatrix(const mrpt::img::TCamera& camera)
{
	return {camera.fx(), 0, camera.cx(), 0, camera.fy(), camera.cy(), 0, 0, 1};
}

bool isPinholeModel(const mrpt::img::TCamera& camera)
{
	return camera.distortion == mrpt::img::DistortionModel::none ||
		camera.distortion == mrpt::img::DistortionModel::plumb_bob;
}

std::vector<double> openCvDistortion(const mrpt::img::TCamera& camera)
{
	if (!isPinholeModel(camera))
		throw std::invalid_argument("openCvDistortion: not a pin-hole distortion model (kannala_brandt)");
	const auto& d = camera.dist;
	auto nonZero = [&](size_t first, size_t end) {
		return std::any_of(d.begin() + long(first), d.begin() + long(end), [](double k) { return k != 0; });
	};
	if (!nonZero(0, d.size())) return {};
	return std::vector<double>(d.begin(), d.begin() + (nonZero(5, 8) ? 8 : 5));
}

bool hasLensDistortion(const mrpt::img::TCamera& camera) { return !openCvDistortion(camera).empty(); }

namespace
{
/** The image's border, a pixel every 1/steps of each side, in order round
 * it (steps 1: its four corners). */
std::vector<cv::Point2d> imageBorder(const mrpt::img::TCamera& camera, int steps)
{
	const double lastU = camera.ncols - 1.0, lastV = camera.nrows - 1.0;
	std::vector<cv::Point2d> border;
	for (int k = 0; k < steps; k++) border.emplace_back(lastU * k / steps, 0);
	for (int k = 0; k < steps; k++) border.emplace_back(lastU, lastV * k / steps);
	for (int k = 0; k < steps; k++) border.emplace_back(lastU * (steps - k) / steps, lastV);
	for (int k = 0; k < steps; k++) border.emplace_back(0, lastV * (steps - k) / steps);
	return border;
}
}  // namespace

std::vector<std::optional<cv::Point2d>> pixelsInView(
	const std::vector<cv::Point3d>& points, const mrpt::img::TCamera& camera)
{
	std::vector<std::optional<cv::Point2d>> pixels(points.size());
	if (points.empty()) return pixels;
	const cv::Mat K(openCvCameraMatrix(camera));
	const bool fisheye = !isPinholeModel(camera);
	// MRPT's kannala_brandt terms are dist[0], [1], [4], [5] (TCamera.h).
	const cv::Vec4d fisheyeD(camera.dist[0], camera.dist[1], camera.dist[4], camera.dist[5]);
	const std::vector<double> D = fisheye ? std::vector<double>() : openCvDistortion(camera);
	const cv::TermCriteria exact(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12);

	// Without a lens the border stays straight: its corners are the whole
	// polygon (a point costs a test per side of it).
	const int steps = fisheye || !D.empty() ? 64 : 1;
	std::vector<cv::Point2d> ideal;
	if (fisheye) cv::fisheye::undistortPoints(imageBorder(camera, steps), ideal, K, fisheyeD, cv::noArray(), cv::noArray(), exact);
	else cv::undistortPoints(imageBorder(camera, steps), ideal, K, D, cv::noArray(), cv::noArray(), exact);
	const std::vector<cv::Point2f> view(ideal.begin(), ideal.end());
	// Its bounding box turns away most points outside before the polygon test.
	float minX = view[0].x, maxX = minX, minY = view[0].y, maxY = minY;
	for (const auto& q : view)
		minX = std::min(minX, q.x), maxX = std::max(maxX, q.x), minY = std::min(minY, q.y), maxY = std::max(maxY, q.y);

	std::vector<cv::Point3d> seen;
	std::vector<size_t> seenIndex;
	for (size_t k = 0; k < points.size(); k++)
	{
		const cv::Point3d& p = points[k];
		if (p.z <= 0) continue;
		const cv::Point2f q(float(p.x / p.z), float(p.y / p.z));
		if (q.x < minX || q.x > maxX || q.y < minY || q.y > maxY || cv::pointPolygonTest(view, q, false) < 0) continue;
		seen.push_back(p);
		seenIndex.push_back(k);
	}
	if (seen.empty()) return pixels;
	std::vector<cv::Point2d> projected;
	const cv::Vec3d noRotation(0, 0, 0), noTranslation(0, 0, 0);
	if (fisheye) cv::fisheye::projectPoints(seen, projected, noRotation, noTranslation, K, fisheyeD);
	else cv::projectPoints(seen, noRotation, noTranslation, K, D, projected);
	for (size_t j = 0; j < seen.size(); j++) pixels[seenIndex[j]] = projected[j];
	return pixels;
}

}  // namespace lvf::common
