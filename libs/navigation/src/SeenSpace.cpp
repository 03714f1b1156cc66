#include <lvfusion/navigation/SeenSpace.h>

#include <algorithm>
#include <cmath>

namespace lvf::navigation
{
namespace
{
/** A voxel counts as seen free once one ray has crossed it: MRPT's first
 * free update takes it from 0.5 to about 0.6. */
constexpr float kSeenFreeAbove = 0.55f;
}  // namespace

SeenSpace::SeenSpace(
	double xMin, double xMax, double yMin, double yMax, const lvf::HeightBand& band, double resolution)
	: m_band(band),
	  m_resolution(resolution),
	  m_xMin(xMin),
	  m_yMin(yMin),
	  m_bandVoxels(std::max(1, int(std::ceil((band.high - band.low) / resolution - 1e-6))))
{
	// Two voxels of room below the band: MRPT 2.5's insertRay() marks a
	// ray's end occupied whatever `endIsOccupied` says, and a ray that ends
	// on the floor must mark those, not the band's lowest voxels.
	m_voxels.setSize(
		{xMin, yMin, band.low - 2 * resolution}, {xMax, yMax, band.low + m_bandVoxels * resolution}, resolution, 0.5f);
}

void SeenSpace::insertRay(const mrpt::math::TPoint3D& from, const mrpt::math::TPoint3D& to)
{
	m_voxels.insertRay(from, to);
}

void SeenSpace::markFree(const mrpt::math::TPoint2D& centre, double radius)
{
	// Voxel centres, by index: stepping positions by the resolution would
	// drift across voxel borders and skip a row now and then.
	const int x0 = index(centre.x - radius, m_xMin), x1 = index(centre.x + radius, m_xMin);
	const int y0 = index(centre.y - radius, m_yMin), y1 = index(centre.y + radius, m_yMin);
	for (int iy = y0; iy <= y1; iy++)
		for (int ix = x0; ix <= x1; ix++)
		{
			const double x = middle(ix, m_xMin), y = middle(iy, m_yMin);
			if (std::hypot(x - centre.x, y - centre.y) > radius) continue;
			for (int iz = 0; iz < m_bandVoxels; iz++)
				m_voxels.setFreenessByPos(float(x), float(y), float(middle(iz, m_band.low)), 1.0f);
		}
}

double SeenSpace::unseenHeight(double x, double y) const
{
	int unseen = 0;
	for (int iz = 0; iz < m_bandVoxels; iz++)
		if (!(m_voxels.getFreenessByPos(float(x), float(y), float(middle(iz, m_band.low))) > kSeenFreeAbove)) unseen++;
	return unseen * m_resolution;
}

}  // namespace lvf::navigation
