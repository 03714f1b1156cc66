#pragma once
// A Middlebury 2014 calib.txt: "key=value" lines, of which the importer needs
// cam0 and cam1 (3x3 intrinsics of the rectified pair, "[f 0 cx; 0 f cy;
// 0 0 1]"), doffs (= cx1 - cx0), baseline [mm], width and height; ndisp, the
// disparity range the scene spans, is read when given (lvf-bench gives it to
// the dense matchers). The other keys (isint, vmin, vmax, dyavg, dymax) are
// not needed.

#include <mrpt/img/TCamera.h>

#include <string>

namespace lvf::middlebury
{
struct MiddleburyCalib
{
	double f = 0;  //!< focal length of both cameras [px]
	double cx0 = 0, cx1 = 0;  //!< principal points' columns, left and right [px]
	double cy = 0;	//!< principal points' row, both cameras [px]
	double doffs = 0;  //!< cx1 - cx0 [px]: Z = baseline * f / (d + doffs)
	double baseline = 0;  //!< [m] (the file says mm)
	int width = 0, height = 0;	//!< [px]
	/** The scene's disparities lie in [0, ndisp) [px] (0: not given). */
	int ndisp = 0;

	/** Depth [m] of a left pixel with ground-truth disparity d [px]. */
	double depth(double d) const { return baseline * f / (d + doffs); }

	mrpt::img::TCamera leftCamera() const;
	mrpt::img::TCamera rightCamera() const;
};

/** Reads and checks `path`. A missing or malformed field, or a calibration
 * that is not a rectified pair (different f or cy, doffs != cx1 - cx0), is an
 * InputError naming the file, the line or the field. */
MiddleburyCalib readMiddleburyCalib(const std::string& path);

}  // namespace lvf::middlebury
