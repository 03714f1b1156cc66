#pragma once
// How near the visual points found so far lie on each bearing seen from the
// camera, for the search's later passes (TOptions::nearestFirstLevels): a
// pixel on a bearing where enough was already found need only be searched
// in front of it, since the fused scan keeps only the nearest obstacle of a
// bearing. Distances and bearings are horizontal, from the camera centre,
// so that every depth along a pixel's ray falls on the same bearing.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lvf::depth
{
class NearestPerBearing
{
   public:
	/** Bins a quarter of a degree wide: finer than the grid's columns
	 * (stride 3 at f = 450 px is 0.38 deg), so a point bounds only the
	 * pixels of its own column and row neighbourhood, never the next
	 * column's (an object's edge there may stand in front of a far wall). */
	static constexpr double kBinWidth = 0.25 * M_PI / 180;

	/** A bearing is bounded once it holds `enough` points, at its
	 * enough-th nearest distance: fewer may be a lone mismatch, or a far
	 * surface that needs every point the rows between can add. */
	NearestPerBearing(const Eigen::Vector3d& camera, size_t enough)
		: m_camera(camera),
		  m_enough(std::max<size_t>(enough, 1)),
		  m_distances(binCount()),
		  m_bound(binCount(), std::numeric_limits<double>::infinity())
	{
	}

	/** A visual point, robot frame. */
	void add(const Eigen::Vector3d& p)
	{
		const double dx = p.x() - m_camera.x(), dy = p.y() - m_camera.y();
		m_distances[bin(std::atan2(dy, dx))].push_back(std::hypot(dx, dy));
	}

	/** After adding points: each bearing's bound from all points so far
	 * (until then, the bounds of the last call; none at first). */
	void finish()
	{
		for (size_t b = 0; b < m_distances.size(); b++)
		{
			auto& d = m_distances[b];
			if (d.size() < m_enough) continue;
			std::nth_element(d.begin(), d.begin() + long(m_enough - 1), d.end());
			m_bound[b] = d[m_enough - 1];
		}
	}

	/** The bound on the bearing of a ray (robot frame) from the camera: a
	 * horizontal distance, infinity where too little was found. */
	double along(const Eigen::Vector3d& ray) const { return m_bound[bin(std::atan2(ray.y(), ray.x()))]; }

   private:
	static size_t binCount() { return static_cast<size_t>(std::ceil(2 * M_PI / kBinWidth)); }
	static size_t bin(double bearing)
	{
		const auto b = static_cast<size_t>(std::floor((bearing + M_PI) / kBinWidth));
		return std::min(b, binCount() - 1);
	}

	Eigen::Vector3d m_camera;
	size_t m_enough;
	std::vector<std::vector<double>> m_distances;
	std::vector<double> m_bound;
};

}  // namespace lvf::depth
