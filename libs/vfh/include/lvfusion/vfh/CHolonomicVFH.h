#pragma once
// VFH+ as an MRPT holonomic reactive method, selectable by name in any MRPT
// reactive navigation INI:
//
//   [CAbstractPTGBasedReactive]
//   holonomic_method = CHolonomicVFH
//   [CHolonomicVFH]
//   ...keys of share/lvfusion/config/vfh.ini...
//
// (the class is registered by lvf::registerAllClasses() or by loading the
// plugin liblvfusion.so).
//
// The adapter from MRPT's input to VFH+. A PTG-based navigator hands every
// holonomic method, per PTG, the TP-obstacles: for each of the PTG's N
// trajectories (direction i at -pi + (i + 0.5) 2pi/N) the normalised distance
// the robot can travel along it before its shape hits something, and the
// target in the same normalised TP coordinates. CHolonomicVFH takes each
// TP-obstacle nearer than maxObstacleDist as one fully certain obstacle cell
// at that distance and direction of the TP plane, and runs the VFH+ cycle on
// those cells with TP-space lengths (fractions of maxObstacleDist, i.e. of
// the navigator's ref_distance):
//  - no robot_radius: a TP distance already is a collision distance of the
//    robot's shape, so only safety_distance enlarges the cells;
//  - no min_turn_radius / masked histogram: every TP direction is a
//    trajectory the vehicle can drive (the PTG encodes its kinematics);
//  - the heading is 0 (TP direction 0 is straight ahead) and the previous
//    direction is the last one returned, in the robot frame of that step:
//    TP-space moves with the robot, so the mu3 term is an approximation;
//  - the hysteresis compares sectors of successive robot frames likewise;
//  - the active window is, by default, the whole TP-space (TOptions says
//    why), cut at the target's TP distance + safety_distance: beyond the
//    target a trajectory's obstacle does not keep the robot from it;
//  - no valley: retried with half the safety distance, then a quarter
//    (safety_fallback); each level is a VFH+ engine of its own, so a
//    fallback's hysteresis and previous direction are those of the last
//    cycle that used it, not of the last cycle (a level below decided in
//    between: the approximation above, over more steps);
//  - speed: VFH's law, times a linear slow-down near the target (as MRPT's
//    VFF); zero when every direction is blocked at every safety level.
// One method object exists per PTG, so each keeps its own VFH+ state.

#include <lvfusion/vfh/CLogFileRecord_VFH.h>
#include <lvfusion/vfh/VfhPlus.h>
#include <mrpt/nav/holonomic/CAbstractHolonomicReactiveMethod.h>

#include <array>
#include <memory>

namespace lvf::vfh
{
class CHolonomicVFH : public mrpt::nav::CAbstractHolonomicReactiveMethod
{
	DEFINE_SERIALIZABLE(CHolonomicVFH, lvf::vfh)

   public:
	/** Section [CHolonomicVFH]; lengths are fractions of maxObstacleDist. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		/** The engine's parameters with TP-space defaults. The window is
		 * the whole TP-space (1.0): the navigator's ref_distance is already
		 * the look-ahead, VFH's window's counterpart, and TP distances run
		 * along curved trajectories. Measured (tests/test_vfh_reactive_nav,
		 * ref_distance 4 m): with VFH's 1.6 m (0.4) the robot stalled
		 * against a block with the target behind it; with 0.8 and 1.0 every
		 * course was completed. Safety distance 0.025: VFH's 0.1 m (one
		 * cell) at a ref_distance of 4 m. */
		VfhParameters vfh = tpSpaceDefaults();
		/** Speed ramps down linearly when the target is nearer than this
		 * [normalised distance] (as MRPT's VFF: 0.10). */
		double targetSlowApproachingDistance = 0.10;
		/** No valley: retry with half the safety distance, then a quarter, before
		 * stopping (CHolonomicVFH.cpp says why). */
		bool safetyFallback = true;

		static VfhParameters tpSpaceDefaults();
		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	TOptions options;

	explicit CHolonomicVFH(const mrpt::config::CConfigFileBase* ini = nullptr);

	void navigate(const NavInput& ni, NavOutput& no) override;
	void initialize(const mrpt::config::CConfigFileBase& ini) override;
	void saveConfigFile(mrpt::config::CConfigFileBase& c) const override;

	double getTargetApproachSlowDownDistance() const override
	{
		return options.targetSlowApproachingDistance;
	}
	void setTargetApproachSlowDownDistance(const double dist) override
	{
		options.targetSlowApproachingDistance = dist;
	}

	/** The adapter's cells: each TP-obstacle nearer than maxObstacleDist
	 * and than `horizon` (a fraction of it) as a certain cell, lengths in
	 * fractions of maxObstacleDist. */
	static std::vector<ObstacleCell> tpObstacleCells(const NavInput& ni, double horizon = 1.0);

   private:
	static constexpr size_t kSafetyLevels = 3;
	/** The engine of safety level `level` (0: options.vfh; 1: half its
	 * safety distance; 2: a quarter), rebuilt whenever `options.vfh` changed
	 * since. Each keeps its own hysteresis and previous direction. */
	VfhPlus& engine(size_t level);
	std::array<std::unique_ptr<VfhPlus>, kSafetyLevels> m_engines;
};

}  // namespace lvf::vfh
