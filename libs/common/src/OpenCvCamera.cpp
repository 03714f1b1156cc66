#include <lvfusion/common/OpenCvCamera.h>

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
	if (camera.distortion == mrpt::img::DistortionModel::none) return {};
	const auto& d = camera.dist;
	const bool rational = d[5] != 0 || d[6] != 0 || d[7] != 0;
	return std::vector<double>(d.begin(), d.begin() + (rational ? 8 : 5));
}

bool hasLensDistortion(const mrpt::img::TCamera& camera)
{
	const auto d = openCvDistortion(camera);
	return std::any_of(d.begin(), d.end(), [](double k) { return k != 0; });
}

}  // namespace lvf::common
