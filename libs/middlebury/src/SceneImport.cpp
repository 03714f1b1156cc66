#include <lvfusion/middlebury/SceneImport.h>
#include <mrpt/poses/CPose3DQuat.h>

namespace lvf::middlebury
{
namespace
{
mrpt::obs::CObservationStereoImages::Ptr stereoObservation(
	const MiddleburyScene& scene, const VirtualRobotFrame& frame, mrpt::Clock::time_point stamp)
{
	auto obs = std::make_shared<mrpt::obs::CObservationStereoImages>();
	obs->sensorLabel = "STEREO";
	obs->timestamp = stamp;
	obs->imageLeft = scene.left;
	obs->imageRight = scene.right;
	obs->hasImageRight = true;
	obs->leftCamera = scene.calib.leftCamera();
	obs->rightCamera = scene.calib.rightCamera();
	// Rectified pair: the right camera is the left one moved along its x.
	obs->rightCameraPose =
		mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(scene.calib.baseline, 0, 0, 0, 0, 0));
	obs->cameraPose = mrpt::poses::CPose3DQuat(frame.cameraPose());
	return obs;
}
}  // namespace

ImportedScene importScene(
	const std::string& dir, const SceneImportOptions& options, mrpt::Clock::time_point stamp)
{
	auto scene = loadMiddleburyScene(dir);
	const FloorPlane floor = fitFloor(scene, options.floor);
	const VirtualRobotFrame frame(floor);
	std::vector<Eigen::Vector3d> points;
	points.reserve(scene.points.size());
	for (const auto& g : scene.points) points.push_back(frame.toRobot(g.camera));

	const ScanBearings bearings = options.apertureRad
		? ScanBearings::fromAperture(*options.apertureRad, options.resolutionRad)
		: cameraFieldOfView(scene.calib, frame, options.resolutionRad);
	auto scan = synthesiseLaser(points, bearings, options.slice, stamp);
	auto truth = truthScan(points, bearings, options.band);
	auto stereo = stereoObservation(scene, frame, stamp);
	return {std::move(scene), floor, frame, bearings, std::move(scan), std::move(stereo), std::move(truth)};
}

}  // namespace lvf::middlebury
