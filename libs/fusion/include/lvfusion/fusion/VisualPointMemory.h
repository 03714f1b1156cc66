#pragma once
// Visual points of earlier frames, carried into the present robot frame by
// odometry, for what the cameras cannot see now (ours, not the paper's).
//
// Why: the cameras' view is narrower than the band the robot sweeps. Close
// to an obstacle only vision found (a low box, a table top), the
// obstacle's heights leave the image — below its bottom edge (the cameras,
// 1 m up and 15 deg down, see the floor from 1.07 m), beyond its side —
// while the laser bearing through it is still in view. The frame then
// has no evidence of it, and the fused scan "forgets" it exactly when the
// robot needs it most (18 of the 39 misses in seeded rooms 1-6 were such
// bearings). The paper keeps such obstacles in its local grid; a remembered
// point keeps them in the fused scan itself, for any MRPT consumer of the
// FUSED scan. Measured (lvf-fuse, recall / phantom rate, without -> with):
// rooms 1-6 0.863 / 0.033 -> 0.891 / 0.033, box room 0.924 -> 0.956 (0.020
// both), corridor desk 0.690 -> 0.715; every phantom count the same or one
// lower (share/doc/lvfusion/measurements.md).
//
// The present frame has the last word wherever it could have looked: a
// remembered point that projects into the part of the left image the
// search covers (in front of the camera, nearer than z_max), and whose
// match would lie inside the right image, is dropped, found again or not,
// so a phantom lives only while it stays out of view.
// Points are forgotten once the robot has travelled `max_travel` since they
// were seen (odometry drifts).

#include <lvfusion/depth/FocusedEpipolarSearch.h>
#include <lvfusion/evaluation/RectifiedStereo.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>

#include <limits>
#include <vector>

namespace lvf::fusion
{
class VisualPointMemory
{
   public:
	/** INI section [VisualPointMemory]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		/** Forget a point once the robot has travelled this far since it was
		 * seen [m]; 0: no memory. A low obstacle leaves the image about 1 m
		 * from the cameras, and is needed until the robot is past it;
		 * odometry drifts ~2 cm per metre. */
		double maxTravel = 1.5;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	/** The part of the rectified left image the present search covers [px],
	 * the depths it searches [m], and where it could not match: a point
	 * whose place in the right image lies outside the columns the right
	 * windows fit in (near the left image's left edge the right camera
	 * does not see what the left one does), or on a pixel rectification
	 * filled from outside either camera's image (a black corner). */
	struct SearchedView
	{
		float firstColumn = 0, lastColumn = 0, firstRow = 0, lastRow = 0;
		double zMin = 0, zMax = 0;
		float firstRightColumn = -std::numeric_limits<float>::infinity();
		float lastRightColumn = std::numeric_limits<float>::infinity();
		/** RectificationEffects' marks; empty: none. */
		cv::Mat1b leftNotImaged, rightNotImaged;
	};

	VisualPointMemory() = default;
	explicit VisualPointMemory(const TOptions& options) : m_options(options) {}

	bool enabled() const { return m_options.maxTravel > 0; }

	/** Moves the memory to the robot's present odometry pose: forgets what
	 * is too old or now in the searched view, and returns the rest in the
	 * present robot frame (u, v, disparity NaN: no pixel of this frame).
	 * A non-finite pose empties the memory. */
	std::vector<lvf::depth::VisualPoint> recall(
		const mrpt::poses::CPose2D& odometry, const lvf::evaluation::RectifiedGeometry& geometry,
		const SearchedView& view);

	/** Adds this frame's points (robot frame), seen at the pose given to the
	 * last recall(). */
	void remember(const std::vector<lvf::depth::VisualPoint>& points);

	size_t size() const { return m_points.size(); }
	void clear() { m_points.clear(), m_hasPose = false; }

   private:
	struct Remembered
	{
		Eigen::Vector3d odom;  //!< in the odometry frame [m]
		double seenAtTravel;  //!< the odometer when it was seen [m]
	};
	TOptions m_options;
	std::vector<Remembered> m_points;
	mrpt::poses::CPose2D m_pose;  //!< of the last recall()
	double m_travel = 0;  //!< distance driven by odometry [m]
	bool m_hasPose = false;
};

}  // namespace lvf::fusion
