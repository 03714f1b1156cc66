#include <lvfusion/common/InputError.h>
#include <lvfusion/common/OpenCvCamera.h>
#include <lvfusion/evaluation/ImageNoise.h>
#include <lvfusion/evaluation/RectifiedStereo.h>
#include <Eigen/Dense>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace lvf::evaluation
{
using lvf::common::InputError;

namespace
{
bool nearlyEqual(double a, double b)
{
	return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

/** Everything that defines the rectification, for change detection. */
std::vector<double> calibrationKey(
	const mrpt::img::TStereoCamera& s, const mrpt::poses::CPose3D& cameraPose)
{
	std::vector<double> key;
	for (const auto* c : {&s.leftCamera, &s.rightCamera})
	{
		key.push_back(c->ncols);
		key.push_back(c->nrows);
		for (int i = 0; i < 9; i++) key.push_back(c->intrinsicParams(i / 3, i % 3));
		key.insert(key.end(), c->dist.begin(), c->dist.end());
	}
	const mrpt::poses::CPose3D right(s.rightCameraPose);
	for (const auto* p : {&right, &cameraPose})
		for (int i = 0; i < 6; i++) key.push_back((*p)[i]);
	return key;
}

/** An image kept in a file beside the rawlog (MRPT's external storage,
 * loaded on first use) read now, so that a missing or unreadable file is
 * this frame's one error line rather than an exception from inside MRPT. */
void loadIfExternal(const mrpt::img::CImage& image, const std::string& record, const std::string& which)
{
	if (!image.isExternallyStored()) return;
	try
	{
		image.forceLoad();
	}
	catch (const std::exception&)
	{
		throw InputError(record, which, "cannot read its file " + image.getExternalStorageFileAbsolutePath());
	}
}

/** A pose as stored in the record, checked before MRPT converts it: MRPT
 * throws its own exception (an "internal error" to the user) on a
 * quaternion that is not a rotation, and passes NaN through silently. */
mrpt::poses::CPose3D storedPose(
	const mrpt::math::TPose3DQuat& p, const std::string& record, const std::string& field)
{
	const auto asText = [&] {
		return mrpt::format("(x y z qr qx qy qz) = (%g %g %g %g %g %g %g)", p.x, p.y, p.z, p.qr, p.qx, p.qy, p.qz);
	};
	for (int i = 0; i < 7; i++)
		if (!std::isfinite(p[i])) throw InputError(record, field, "not a finite pose: " + asText());
	// MRPT renormalises rounding drift itself; a squared norm 1e-3 off is
	// far beyond rounding yet not what any stored rotation carries.
	const double squaredNorm = p.qr * p.qr + p.qx * p.qx + p.qy * p.qy + p.qz * p.qz;
	if (!(std::abs(squaredNorm - 1.0) < 1e-3))
		throw InputError(record, field,
			mrpt::format("quaternion is not a rotation (squared norm %g): ", squaredNorm) + asText());
	return mrpt::poses::CPose3D(mrpt::poses::CPose3DQuat(p));
}

}  // namespace

cv::Mat1b toGrey(const mrpt::img::CImage& image)
{
	const mrpt::img::CImage grey =
		image.isColor() ? image.grayscale() : mrpt::img::CImage(image, mrpt::img::SHALLOW_COPY);
	return grey.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
}

void RectifiedStereo::prepare(
	const mrpt::obs::CObservationStereoImages& obs, const std::string& record)
{
	if (!obs.hasImageRight || obs.imageRight.isEmpty())
		throw InputError(record, "", "stereo observation has no right image");
	loadIfExternal(obs.imageLeft, record, "left image");
	loadIfExternal(obs.imageRight, record, "right image");
	const auto calib = obs.getStereoCameraParams();
	for (const auto& [image, cam, which] :
		 {std::tuple{&obs.imageLeft, &calib.leftCamera, "left"},
		  std::tuple{&obs.imageRight, &calib.rightCamera, "right"}})
	{
		if (!(cam->fx() > 0 && cam->fy() > 0 && std::isfinite(cam->fx()) &&
			  std::isfinite(cam->fy())))
			throw InputError(record, std::string(which) + " camera",
				"focal length must be positive and finite (fx " +
					std::to_string(cam->fx()) + ", fy " + std::to_string(cam->fy()) + ")");
		if (!lvf::common::isPinholeModel(*cam))
			throw InputError(record, std::string(which) + " camera",
				"fish-eye (kannala_brandt) distortion is not supported: give images rectified by "
				"cv::fisheye, or a plumb_bob calibration");
		if (image->getWidth() != cam->ncols || image->getHeight() != cam->nrows)
			throw InputError(record, std::string(which) + " image",
				std::to_string(image->getWidth()) + "x" + std::to_string(image->getHeight()) +
					" pixels, but the calibration says " + std::to_string(cam->ncols) +
					"x" + std::to_string(cam->nrows));
	}
	const mrpt::poses::CPose3D right = storedPose(calib.rightCameraPose, record, "rightCameraPose");
	const double baseline = right.translation().norm();
	if (!(baseline > 1e-6 && right.x() > 0))
		throw InputError(record, "rightCameraPose",
			"the right camera must be to the right of the left one (x > 0), got x = " +
				std::to_string(right.x()));

	const mrpt::poses::CPose3D cameraPose = storedPose(obs.cameraPose.asTPose(), record, "cameraPose");
	if (m_prepared && calibrationKey(calib, cameraPose) == calibrationKey(m_calibration, m_cameraPose))
		return;
	m_calibration = calib;
	m_cameraPose = cameraPose;
	m_prepared = true;

	const auto& L = calib.leftCamera;
	const auto& R = calib.rightCamera;
	m_geometry.size = cv::Size(static_cast<int>(L.ncols), static_cast<int>(L.nrows));
	const bool alreadyRectified = !lvf::common::hasLensDistortion(L) && !lvf::common::hasLensDistortion(R) &&
		nearlyEqual(L.fx(), L.fy()) && nearlyEqual(L.fx(), R.fx()) &&
		nearlyEqual(L.fy(), R.fy()) && nearlyEqual(L.cy(), R.cy()) &&
		right.getRotationMatrix().asEigen().isIdentity(1e-9) &&
		std::abs(right.y()) < 1e-9 * baseline && std::abs(right.z()) < 1e-9 * baseline;
	if (alreadyRectified)
	{
		m_mapLeftX = m_mapLeftY = m_mapRightX = m_mapRightY = cv::Mat();
		m_leftNotImaged = m_rightNotImaged = cv::Mat1b();
		m_geometry.f = L.fx();
		m_geometry.cx = L.cx();
		m_geometry.cy = L.cy();
		m_geometry.cxOffset = R.cx() - L.cx();
		m_geometry.baseline = baseline;
		m_geometry.leftPose = cameraPose;
		return;
	}

	// OpenCV wants the transform from left-camera to right-camera
	// coordinates, the inverse of MRPT's pose of the right camera.
	const mrpt::poses::CPose3D leftInRight = -right;
	cv::Mat Rlr(3, 3, CV_64F), Tlr(3, 1, CV_64F);
	const auto rot = leftInRight.getRotationMatrix();
	for (int i = 0; i < 3; i++)
	{
		for (int j = 0; j < 3; j++) Rlr.at<double>(i, j) = rot(i, j);
		Tlr.at<double>(i) = leftInRight[i];
	}
	const cv::Matx33d KL = lvf::common::openCvCameraMatrix(L), KR = lvf::common::openCvCameraMatrix(R);
	const std::vector<double> DL = lvf::common::openCvDistortion(L), DR = lvf::common::openCvDistortion(R);
	cv::Mat R1, R2, P1, P2, Q;
	// Zero disparity at infinity (equal cx).
	cv::stereoRectify(
		KL, DL, KR, DR, m_geometry.size, Rlr, Tlr, R1, R2, P1, P2, Q, cv::CALIB_ZERO_DISPARITY, m_alpha);
	cv::initUndistortRectifyMap(
		KL, DL, R1, P1, m_geometry.size, CV_16SC2,
		m_mapLeftX, m_mapLeftY);
	cv::initUndistortRectifyMap(
		KR, DR, R2, P2, m_geometry.size, CV_16SC2,
		m_mapRightX, m_mapRightY);
	// Where the maps reach outside the images: remap an all-white image.
	const cv::Mat1b white(m_geometry.size, uint8_t(255));
	auto notImaged = [&](const cv::Mat& mapX, const cv::Mat& mapY) {
		cv::Mat1b imaged;
		cv::remap(white, imaged, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
		const cv::Mat1b outside = imaged < 255;
		return cv::countNonZero(outside) ? outside : cv::Mat1b();
	};
	m_leftNotImaged = notImaged(m_mapLeftX, m_mapLeftY);
	m_rightNotImaged = notImaged(m_mapRightX, m_mapRightY);
	m_geometry.f = P1.at<double>(0, 0);
	m_geometry.cx = P1.at<double>(0, 2);
	m_geometry.cy = P1.at<double>(1, 2);
	m_geometry.cxOffset = P2.at<double>(0, 2) - P1.at<double>(0, 2);
	m_geometry.baseline = -P2.at<double>(0, 3) / P2.at<double>(0, 0);
	// R1 maps original-left coordinates to rectified ones (X_rect = R1 X), so
	// the rectified camera is the original one rotated by R1 transposed.
	mrpt::math::CMatrixDouble33 rectToLeft;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) rectToLeft(i, j) = R1.at<double>(j, i);
	mrpt::poses::CPose3D rectified;
	rectified.setRotationMatrix(rectToLeft);
	m_geometry.leftPose = cameraPose + rectified;
}

RectificationEffects RectifiedStereo::rectify(
	const mrpt::obs::CObservationStereoImages& obs, cv::Mat1b& left,
	cv::Mat1b& right) const
{
	const cv::Mat1b greyLeft = toGrey(obs.imageLeft);
	const cv::Mat1b greyRight = toGrey(obs.imageRight);
	if (!remaps())
	{
		left = greyLeft;
		right = greyRight;
		return {};
	}
	cv::remap(greyLeft, left, m_mapLeftX, m_mapLeftY, cv::INTER_LINEAR);
	cv::remap(greyRight, right, m_mapRightX, m_mapRightY, cv::INTER_LINEAR);
	return {estimateNoiseStd(greyLeft), m_leftNotImaged, m_rightNotImaged};
}

}  // namespace lvf::evaluation
