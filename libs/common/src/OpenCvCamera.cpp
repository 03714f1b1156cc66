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
	const auto& d = camera.dist;
	auto nonZero = [&](size_t first, size_t end) {
		return std::any_of(d.begin() + long(first), d.begin() + long(end), [](double k) { return k != 0; });
	};
	if (!nonZero(0, d.size())) return {};
	return std::vector<double>(d.begin(), d.begin() + (nonZero(5, 8) ? 8 : 5));
}

bool hasLensDistortion(const mrpt::img::TCamera& camera) { return !openCvDistortion(camera).empty(); }

}  // namespace lvf::common
