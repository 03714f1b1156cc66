#include "SeenRays.h"

#include <mrpt/poses/CPose3D.h>


namespace lvf::navigation
{
using lvf::evaluation::PixelState;

void carveSeenRays(
	const lvf::fusion::CLaserStereoFusion::Result& frame, const mrpt::poses::CPose2D& robot, SeenSpace& space)
{
	const auto& g = frame.geometry;
	const auto& e = frame.evaluation;
	const mrpt::poses::CPose3D pose(robot);
	const Eigen::Vector3d camera = g.cameraCentre();
	const mrpt::math::TPoint3D from = pose.composePoint({camera.x(), camera.y(), camera.z()});
	auto toWorld = [&](const Eigen::Vector3d& p) { return pose.composePoint({p.x(), p.y(), p.z()}); };

	for (int v = 0; v < e.state.rows; v++)
		for (int u = 0; u < e.state.cols; u++)
		{
			const auto s = static_cast<PixelState>(e.state(v, u));
			const float d = e.modelDisparity(v, u);
			if (s != PixelState::Consistent || d <= 0) continue;
			const double depth = g.fB() / d;
			space.insertRay(from, toWorld(camera + depth * g.robotRay(u, v)));
		}
	for (const auto& p : frame.search.points) space.insertRay(from, toWorld(p.robot));
}

}  // namespace lvf::navigation
