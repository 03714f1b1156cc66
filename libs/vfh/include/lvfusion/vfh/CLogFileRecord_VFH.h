#pragma once
// What CHolonomicVFH decided in one navigation step, stored in MRPT's
// navigation logs (.reactivenavlog). navlog-viewer (with the plugin loaded:
// `navlog-viewer -l liblvfusion.so`) draws `dirs_eval` as polar curves over
// each PTG's TP-obstacles, one value per PTG direction in [0, 1]:
//   [0] free-ness of the primary histogram: 1 - min(1, H^p / tau_high)
//   [1] the masked histogram: 1 free, 0 blocked
//   [2] (last, the "final score") 1 - g/g_worst for free directions, g the
//       VFH+ cost a candidate at the centre of their sector would have,
//       g_worst = (mu1 + mu2 + mu3) * sectors/2; 0 where blocked.
// The histograms themselves, per VFH sector, are kept alongside.

#include <mrpt/nav/holonomic/CHolonomicLogFileRecord.h>

#include <cstdint>
#include <vector>

namespace lvf::vfh
{
class CLogFileRecord_VFH : public mrpt::nav::CHolonomicLogFileRecord
{
	DEFINE_SERIALIZABLE(CLogFileRecord_VFH, lvf::vfh)

   public:
	std::vector<double> primaryHistogram;	//!< H^p per sector (sector 0 at -pi)
	std::vector<uint8_t> binaryHistogram;	//!< H^b, 1 = blocked
	std::vector<uint8_t> maskedHistogram;	//!< H^m, 1 = blocked
	std::vector<double> candidateDirections;  //!< [rad]
	std::vector<double> candidateCosts;		  //!< VFH+ g of each candidate
	double targetDirection = 0;	 //!< [rad]
	double chosenDirection = 0;	 //!< [rad], meaningful if found
	bool found = false;			 //!< false: all blocked, robot told to stop
	double speedFactor = 0;		 //!< VFH speed law, fraction of max speed
	double tauLow = 0, tauHigh = 0;	 //!< thresholds used for H^b
};

}  // namespace lvf::vfh
