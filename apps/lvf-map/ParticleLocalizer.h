#pragma once
// MRPT's particle-filter localisation (CMonteCarloLocalization2D driven by
// CParticleFilter), set up as MRPT's pf-localization does: particles spread
// uniformly over a box (or over its free cells), then per step the odometry
// action moves them and the laser scan's likelihood in the map weighs them.

#include "LocalizationConfig.h"
#include "MapRun.h"

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

namespace lvf::apps
{
class ParticleLocalizer
{
   public:
	/** Particles start within [initMin, initMax]. */
	ParticleLocalizer(
		const LocalizationConfig& config, const mrpt::maps::CMultiMetricMap::Ptr& map,
		const mrpt::math::TPose2D& initMin, const mrpt::math::TPose2D& initMax, bool onFreeSpace);

	/** One filter step; returns the mean of the particles. */
	mrpt::poses::CPose2D update(const MapStep& step);
	size_t particles() const { return m_pdf.size(); }

   private:
	mrpt::slam::CMonteCarloLocalization2D m_pdf;
	mrpt::bayes::CParticleFilter m_filter;
};

}  // namespace lvf::apps
