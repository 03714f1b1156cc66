#pragma once
// One Middlebury 2014 scene folder (im0.png, im1.png, calib.txt,
// disp0GT.pfm, mask0nocc.png), read and checked, and its ground truth as 3D
// points in the left camera's frame (MRPT camera axes: x right, y down,
// z forward).

#include <lvfusion/middlebury/MiddleburyCalib.h>

#include <Eigen/Core>
#include <mrpt/img/CImage.h>
#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

namespace lvf::middlebury
{
struct GroundTruthPoint
{
	int u = 0, v = 0;  //!< left-image pixel [px]
	Eigen::Vector3d camera;	 //!< the point in the left camera's frame [m]
};

struct MiddleburyScene
{
	std::string name;  //!< the folder's name, e.g. "Motorcycle"
	std::string dir;
	MiddleburyCalib calib;
	mrpt::img::CImage left, right;
	cv::Mat disparity;	//!< CV_32FC1, rows top to bottom [px]; inf = unknown
	cv::Mat mask;  //!< CV_8UC1: 0 no ground truth, 128 occluded in im1, 255 seen by both
	/** Every pixel with known disparity (finite, mask != 0, in front of the
	 * camera), in row-major order. Occluded pixels (mask 128) are kept: their
	 * disparity is ground truth for the left view, only im1 cannot see them. */
	std::vector<GroundTruthPoint> points;
	size_t unknownPixels = 0;  //!< skipped: inf, mask 0, or d + doffs <= 0

	/** Path of `fileName` inside the scene folder. */
	std::string file(const std::string& fileName) const;
};

/** Reads and checks every file of `dir`: each must exist and agree with
 * calib.txt's width and height. Throws InputError naming the file (and its
 * line, field or header entry) otherwise. */
MiddleburyScene loadMiddleburyScene(const std::string& dir);

}  // namespace lvf::middlebury
