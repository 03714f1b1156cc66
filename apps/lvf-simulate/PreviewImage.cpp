#include "PreviewImage.h"

#include <mrpt/vision/pinhole.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace lvf::apps
{
namespace
{
/** Draws the robot-frame point (x, y, z) as a dot if the left camera sees it. */
void drawPoint(
	cv::Mat& canvas, const mrpt::obs::CObservationStereoImages& stereo,
	double x, double y, double z, const cv::Scalar& colour)
{
	const auto p = mrpt::poses::CPose3D(stereo.cameraPose).inverseComposePoint({x, y, z});
	if (p.z <= 0.05) return;
	mrpt::img::TPixelCoordf px;
	mrpt::vision::pinhole::projectPoint_with_distortion(p, stereo.leftCamera, px);
	cv::circle(canvas, cv::Point(cvRound(px.x), cvRound(px.y)), 2, colour, cv::FILLED);
}
}  // namespace

void writePreviewImage(
	const std::string& path,
	const lvf::simulation::CStereoLaserSimulator::Frame& frame,
	const std::vector<bool>& hidden, const lvf::simulation::RobotBody& robot)
{
	const auto& stereo = *frame.stereo;
	const auto& scan = *frame.scan;
	cv::Mat canvas;
	cv::cvtColor(stereo.imageLeft.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), canvas,
				 cv::COLOR_GRAY2BGR);
	const auto& laser = scan.sensorPose;
	for (size_t i = 0; i < scan.getScanSize(); i++)
	{
		const double b = scan.getScanAngle(i);
		if (hidden[i])
		{
			const double r = frame.truthScan[i];
			double x, y, z;
			laser.composePoint(r * std::cos(b), r * std::sin(b), 0, x, y, z);
			for (double h = robot.obstacleMinHeight; h <= robot.height; h += 0.05)
				drawPoint(canvas, stereo, x, y, h, {0, 0, 255});
		}
		if (scan.getScanRangeValidity(i))
		{
			const double r = scan.getScanRange(i);
			double x, y, z;
			laser.composePoint(r * std::cos(b), r * std::sin(b), 0, x, y, z);
			drawPoint(canvas, stereo, x, y, z, {0, 255, 0});
		}
	}
	cv::imwrite(path, canvas);
}

}  // namespace lvf::apps
