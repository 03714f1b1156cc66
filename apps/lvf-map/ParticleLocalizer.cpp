#include "ParticleLocalizer.h"

#include <lvfusion/common/InputError.h>
#include <mrpt/core/format.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

namespace lvf::apps
{
ParticleLocalizer::ParticleLocalizer(
	const LocalizationConfig& config, const mrpt::maps::CMultiMetricMap::Ptr& map,
	const mrpt::math::TPose2D& initMin, const mrpt::math::TPose2D& initMax, bool onFreeSpace)
{
	m_pdf.options = config.monteCarlo;
	m_pdf.options.metricMap = map;
	m_filter.m_options = config.pf;
	if (onFreeSpace)
	{
		auto grid = map->mapByClass<mrpt::maps::COccupancyGridMap2D>();
		if (!grid)
			throw lvf::common::InputError(
				"[LocalizationExperiment] init_PDF_mode", "", "0 (free cells) needs an occupancy grid in [MetricMap]");
		// 0.7: pf-localization's threshold for "free" cells. MRPT asserts
		// that the box holds some; a box off the map's free space is the
		// user's to fix, so it is told as such.
		try
		{
			m_pdf.resetUniformFreeSpace(
				grid.get(), 0.7f, static_cast<int>(config.particles), initMin.x, initMax.x, initMin.y, initMax.y,
				initMin.phi, initMax.phi);
		}
		catch (const std::exception& e)
		{
			throw lvf::common::InputError(
				config.source, "[LocalizationExperiment] init_PDF_min_*, init_PDF_max_*",
				mrpt::format(
					"the initial box x [%g, %g] m, y [%g, %g] m holds no free cell of the prior map (init_PDF_mode = "
					"0 spreads the particles over those): %s",
					initMin.x, initMax.x, initMin.y, initMax.y, lvf::common::exceptionMessage(e).c_str()));
		}
	}
	else
		m_pdf.resetUniform(
			initMin.x, initMax.x, initMin.y, initMax.y, initMin.phi, initMax.phi, static_cast<int>(config.particles));
	m_filter.setVerbosityLevel(mrpt::system::LVL_ERROR);
	m_pdf.setVerbosityLevel(mrpt::system::LVL_ERROR);
}

mrpt::poses::CPose2D ParticleLocalizer::update(const MapStep& step)
{
	m_filter.executeOn(m_pdf, step.action.get(), step.laserFrame.get());
	mrpt::poses::CPose2D mean;
	m_pdf.getMean(mean);
	return mean;
}

}  // namespace lvf::apps
