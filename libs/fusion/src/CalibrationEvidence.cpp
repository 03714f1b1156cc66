#include <lvfusion/fusion/CalibrationEvidence.h>

#include <Eigen/Dense>
#include <cmath>

namespace lvf::fusion
{
using lvf::evaluation::PixelState;

/** The model's surface at a pixel is the floor when its disparity is the
 * floor's along that ray to this share: the floor computed two ways (the
 * model's ray cast, the row's ray here) differs by rounding only. (The
 * search asks the same of the point's height: FocusedEpipolarSearch.cpp's
 * kOnTheFloor.) */
constexpr double kFloorDisparityShare = 1e-3;

CalibrationEvidence calibrationEvidence(
	const lvf::evaluation::RectifiedGeometry& g, const lvf::evaluation::ModelEvaluation& evaluation,
	double floorHeight, double agreeingNcc)
{
	CalibrationEvidence out;
	const double height = g.leftPose.z() - floorHeight;	 // camera above the floor [m]
	// The z row of robotRay()'s rotation, taken once rather than with each
	// pixel's ray, and summed in the same order.
	const Eigen::Matrix3d R = g.leftPose.getRotationMatrix().asEigen();
	const double r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
	// Over the grid's own rows and columns, reading its values by index.
	const lvf::evaluation::PixelGrid& grid = evaluation.grid;
	for (int j = 0; j < evaluation.gridNcc.rows; j++)
	{
		const int v = grid.first + j * grid.stride;
		const double r21y = r21 * g.rayY(v);
		const float* ncc = evaluation.gridNcc.ptr<float>(j);
		for (int i = 0; i < evaluation.gridNcc.cols; i++)
		{
			const int u = grid.first + i * grid.stride;
			const auto state = static_cast<PixelState>(evaluation.state(v, u));
			if (state != PixelState::Consistent && state != PixelState::Inconsistent) continue;
			const bool agrees = ncc[i] >= agreeingNcc;
			out.judged++;
			out.disagreeing += !agrees;
			// Depth Z of the floor along this pixel's ray: height + Z ray.z = 0.
			const double down = -(r20 * g.rayX(u) + r21y + r22);
			if (down <= 0) continue;
			const double floorDisparity = g.fB() * down / height;
			if (std::abs(evaluation.modelDisparity(v, u) - floorDisparity) > kFloorDisparityShare * floorDisparity) continue;
			out.floorJudged++;
			out.floorAgreeing += agrees;
		}
	}
	return out;
}

}  // namespace lvf::fusion
