#include "PreviewImage.h"

#include <lvfusion/common/OpenCvCamera.h>
#include <lvfusion/common/WrittenFiles.h>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace lvf::apps
{
void writePreviewImage(
	const std::string& path,
	const lvf::simulation::CStereoLaserSimulator::Frame& frame,
	const std::vector<bool>& hidden, const lvf::simulation::RobotBody& robot)
{
	const auto& stereo = *frame.stereo;
	const auto& scan = *frame.scan;
	const mrpt::poses::CPose3D camera(stereo.cameraPose);
	// Robot-frame points to mark, in the camera's frame, and their colours.
	std::vector<cv::Point3d> points;
	std::vector<cv::Scalar> colours;
	auto mark = [&](double x, double y, double z, const cv::Scalar& colour) {
		const auto p = camera.inverseComposePoint({x, y, z});
		points.emplace_back(p.x, p.y, p.z);
		colours.push_back(colour);
	};
	const auto& laser = scan.sensorPose;
	for (size_t i = 0; i < scan.getScanSize(); i++)
	{
		const double b = scan.getScanAngle(i);
		if (hidden[i])
		{
			const double r = frame.truthScan[i];
			double x, y, z;
			laser.composePoint(r * std::cos(b), r * std::sin(b), 0, x, y, z);
			for (double h = robot.obstacleMinHeight; h <= robot.height; h += 0.05) mark(x, y, h, {0, 0, 255});
		}
		if (scan.getScanRangeValidity(i))
		{
			const double r = scan.getScanRange(i);
			double x, y, z;
			laser.composePoint(r * std::cos(b), r * std::sin(b), 0, x, y, z);
			mark(x, y, z, {0, 255, 0});
		}
	}
	cv::Mat canvas;
	cv::cvtColor(stereo.imageLeft.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), canvas,
				 cv::COLOR_GRAY2BGR);
	// Only what the left camera sees, through its lens.
	const auto pixels = lvf::common::pixelsInView(points, stereo.leftCamera);
	for (size_t k = 0; k < points.size(); k++)
		if (pixels[k]) cv::circle(canvas, cv::Point(cvRound(pixels[k]->x), cvRound(pixels[k]->y)), 2, colours[k], cv::FILLED);
	lvf::common::writeImage(path, canvas);
}

}  // namespace lvf::apps
