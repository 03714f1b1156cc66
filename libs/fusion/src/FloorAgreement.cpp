#include <lvfusion/fusion/FloorAgreement.h>

#include <Eigen/Dense>
#include <cmath>

namespace lvf::fusion
{
using lvf::evaluation::PixelState;

namespace
{
bool judged(const lvf::evaluation::ModelEvaluation& e, int v, int u)
{
	const auto state = static_cast<PixelState>(e.state(v, u));
	return state == PixelState::Consistent || state == PixelState::Inconsistent;
}
}  // namespace

FloorAgreement floorAgreement(
	const lvf::evaluation::RectifiedGeometry& g, const lvf::evaluation::ModelEvaluation& evaluation,
	double floorHeight, double agreeingNcc, int stride)
{
	FloorAgreement out;
	const Eigen::Matrix3d R = g.leftPose.getRotationMatrix().asEigen();
	const double height = g.leftPose.z() - floorHeight;	 // camera above the floor [m]
	for (int v = 0; v < g.size.height; v += stride)
		for (int u = 0; u < g.size.width; u += stride)
		{
			if (!judged(evaluation, v, u)) continue;
			// Depth Z of the floor along this pixel's ray: height + Z ray.z = 0.
			const double down = -(R * Eigen::Vector3d(g.rayX(u), g.rayY(v), 1.0)).z();
			if (down <= 0) continue;
			const double floorDisparity = g.fB() * down / height;
			if (std::abs(evaluation.modelDisparity(v, u) - floorDisparity) > 1e-3 * floorDisparity) continue;
			out.judged++;
			out.consistent += evaluation.ncc(v, u) >= agreeingNcc;
		}
	return out;
}

double disagreeingShare(const lvf::evaluation::ModelEvaluation& evaluation, double agreeingNcc)
{
	size_t judgedPixels = 0, disagreeing = 0;
	for (int v = 0; v < evaluation.state.rows; v++)
		for (int u = 0; u < evaluation.state.cols; u++)
			if (judged(evaluation, v, u)) judgedPixels++, disagreeing += evaluation.ncc(v, u) < agreeingNcc;
	return judgedPixels ? double(disagreeing) / double(judgedPixels) : 0.0;
}

}  // namespace lvf::fusion
