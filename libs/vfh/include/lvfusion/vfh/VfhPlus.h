#pragma once
// One VFH+ cycle (Ulrich & Borenstein 1998) from an active window to a
// steering direction and a speed: primary histogram (enlarged cells,
// optional VFH smoothing) -> binary histogram (hysteresis) -> masked
// histogram (turning limits) -> valleys -> cheapest candidate -> speed by
// VFH's law (Borenstein & Koren 1991, §4). The object keeps what VFH+
// carries between cycles: the binary histogram and the previous direction.
//
// All angles are in the frame of the cells' offsets (see ActiveWindow.h).

#include <lvfusion/vfh/ActiveWindow.h>
#include <lvfusion/vfh/BinaryHistogram.h>
#include <lvfusion/vfh/MaskedHistogram.h>
#include <lvfusion/vfh/PolarSectors.h>
#include <lvfusion/vfh/SteeringSelection.h>
#include <lvfusion/vfh/VfhParameters.h>

#include <optional>
#include <vector>

namespace lvf::vfh
{
class VfhPlus
{
   public:
	explicit VfhPlus(const VfhParameters& p = VfhParameters());

	struct Result
	{
		std::vector<double> primary;   //!< H^p, after the optional smoothing
		std::vector<uint8_t> binary;   //!< H^b, 1 = blocked
		std::vector<uint8_t> masked;   //!< H^m, 1 = blocked
		TurningLimits limits;
		std::vector<Valley> valleys;
		std::vector<Candidate> candidates;
		bool found = false;		   //!< false: every direction blocked, stop
		double direction = 0;	   //!< chosen steering direction [rad]
		double speedFactor = 0;	   //!< speed / v_max by VFH's law, 0 if !found
		double targetCoordinate = 0;	//!< target's sector coordinate
	};

	/** One cycle. `targetDirection` and `heading` in the cells' frame [rad].
	 * The previous direction is this object's last choice (the heading
	 * before the first). */
	Result step(const std::vector<ObstacleCell>& cells, double targetDirection, double heading);

	/** Forget the hysteresis state and the previous direction. */
	void reset();

	const VfhParameters& parameters() const { return m_p; }
	const PolarSectors& sectors() const { return m_sectors; }
	/** Direction chosen by the last successful cycle, if any. */
	std::optional<double> previousDirection() const { return m_previous; }

   private:
	VfhParameters m_p;
	PolarSectors m_sectors;
	BinaryHistogram m_binary;
	std::optional<double> m_previous;
};

}  // namespace lvf::vfh
