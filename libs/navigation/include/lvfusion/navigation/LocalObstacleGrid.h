#pragma once
// The robot's memory of obstacles, as two MRPT occupancy grids of the same
// geometry, fed at the robot's pose:
//  - the laser grid: every laser scan, as usual;
//  - the vision grid: the fused scan, but only the bearings the cameras see.
// A cell is an obstacle when either grid says so. The split matters: a laser
// ray passing *under* a table top says nothing about the top, so laser free
// space must not erase what vision found; only vision looking again can. The
// navigator is fed these cells rather than the last scan, so an overhang
// stays an obstacle after it leaves the cameras' narrow view (the paper's
// local occupancy grid, Sects. 5-6). Optionally (trackSeenSpace) a third memory, in 3D:
// where the cameras have seen through the robot's height band (SeenSpace.h),
// for the plan to keep off what they have not.

#include <lvfusion/navigation/SeenSpace.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <opencv2/core.hpp>

#include <memory>
#include <vector>

namespace lvf::navigation
{
class LocalObstacleGrid
{
   public:
	/** Covers [xMin, xMax] x [yMin, yMax] (world frame) at `resolution`;
	 * a cell is an obstacle when its free probability is below `occupiedBelow`.
	 * `visionMargin` [m]: the navigator (obstaclesNear) also senses the cells
	 * this near an obstacle only vision found. Vision places an obstacle's
	 * edge to a bin of the fused scan and a few centimetres of range, and
	 * sees a floating box only from where it looked, so the laser's exact
	 * edges need no margin and vision's do. */
	LocalObstacleGrid(
		double xMin, double xMax, double yMin, double yMax, double resolution,
		double occupiedBelow, double visionMargin = 0);

	void insertLaser(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot);
	/** `scan`'s bearings out of the cameras' view must be marked invalid:
	 * they are left alone, not taken as free space. */
	void insertVision(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot);

	/** The robot stands at `robot`: nothing is in the band within `radius`
	 * of it, so the vision grid's cells there are free, and never an
	 * overhang's assumed far part (the cameras cannot see under the robot,
	 * nor the ground its body has swept). */
	void markTraversed(const mrpt::poses::CPose2D& robot, double radius);

	bool obstacle(int cx, int cy) const;
	/** Centres of obstacle cells within `range` of the robot, in the robot's
	 * frame (what CRobot2NavInterface::senseObstacles returns). */
	void obstaclesNear(
		const mrpt::poses::CPose2D& robot, double range, mrpt::maps::CSimplePointsMap& out) const;

	/** Both grids in one, for planners: per cell the lower free
	 * probability of the two, so a cell is an obstacle there (below
	 * `occupiedBelow`) exactly when obstacle() says so. */
	mrpt::maps::COccupancyGridMap2D obstacleMap() const;
	/** Marks occupied in `map` (an obstacleMap() of this grid) the cells
	 * vision never looked at (its grid's prior, untouched) within `depth`
	 * of a cell only vision found occupied (the laser's grid does not call
	 * it an obstacle): an overhang's far part, behind the faces the cameras
	 * saw, for planners to keep off. */
	void assumeOverhangDepth(double depth, mrpt::maps::COccupancyGridMap2D& map) const;
	/** A disk of the floor [m]. */
	struct Disk
	{
		mrpt::math::TPoint2D centre;
		double radius = 0;
	};
	/** From now on obstaclesNear() also returns the cells
	 * assumeOverhangDepth(depth) would mark, so that the navigator keeps off
	 * what the plan keeps off -- except those within `robotClearance` of the
	 * robot (they would box it in) or inside one of `open` (a path that had
	 * to go through them, the target); depth 0: none. */
	void senseAssumedOverhangs(double depth, std::vector<Disk> open = {}, double robotClearance = 0);

	/** Also keeps where the cameras have seen through the band (SeenSpace,
	 * voxels of the grid's resolution): off until this is called. */
	void trackSeenSpace(const lvf::HeightBand& band);
	/** From now on (with trackSeenSpace()) an overhang's assumed far part
	 * (assumeOverhangDepth) also takes the cells the vision grid calls free
	 * whose column is unseen(minHeight): a ray under a floating box clears
	 * its cells in 2D, not in 3D. */
	void assumeOverhangsWhereUnseen(double minHeight) { m_overhangUnseenMinHeight = minHeight; }
	/** Null unless trackSeenSpace() was called. */
	SeenSpace* seenSpace() { return m_seen.get(); }
	/** Whether at least `minHeight` of the band over (x, y) has not been
	 * seen free (false without trackSeenSpace()). */
	bool unseen(double x, double y, double minHeight) const;
	/** Marks occupied in `map` (an obstacleMap() of this grid) the cells
	 * `from` to `radius` away from `robot` that are unseen(minHeight). */
	void assumeUnseenNear(
		const mrpt::math::TPoint2D& robot, double from, double radius, double minHeight,
		mrpt::maps::COccupancyGridMap2D& map) const;

	/** Cell geometry (both grids share it). */
	const mrpt::maps::COccupancyGridMap2D& geometry() const { return m_laser; }

   private:
	/** MRPT grows a grid to take in a scan's reach, and the two scans reach
	 * differently (the cameras' view is narrower): both are grown to the
	 * union, so that a cell index means the same place in both. */
	void keepOneGeometry();
	/** Of the cell window [x0, x1] x [y0, y1]: 255 where a cell only vision
	 * found occupied lies within `distance` (rounded up to whole cells). */
	cv::Mat1b nearVisionOnly(double distance, int x0, int y0, int x1, int y1) const;
	/** Of the cell window: 255 where assumeOverhangDepth(depth) marks a cell. */
	cv::Mat1b assumedOverhang(double depth, int x0, int y0, int x1, int y1) const;

	mrpt::maps::COccupancyGridMap2D m_laser, m_vision;
	std::unique_ptr<SeenSpace> m_seen;
	float m_occupiedBelow;
	double m_visionMargin;
	double m_sensedOverhangDepth = 0;
	std::vector<Disk> m_sensedOverhangOpen;
	double m_sensedOverhangRobotClearance = 0;
	double m_overhangUnseenMinHeight = 0;  //!< 0: the 2D vision grid alone says what was looked at
};

}  // namespace lvf::navigation
