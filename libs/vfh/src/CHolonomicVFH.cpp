#include <lvfusion/common/IniSection.h>
#include <lvfusion/vfh/CHolonomicVFH.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>

IMPLEMENTS_SERIALIZABLE(CHolonomicVFH, mrpt::nav::CAbstractHolonomicReactiveMethod, lvf::vfh)

namespace lvf::vfh
{
VfhParameters CHolonomicVFH::TOptions::tpSpaceDefaults()
{
	VfhParameters p;
	p.windowRadius = 1.0;
	p.safetyDistance = 0.025;
	p.robotRadius = 0;	// in the TP distances already (see the header)
	p.minTurnRadius = 0;  // in the PTG's trajectories already
	return p;
}

void CHolonomicVFH::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	vfh.load(ini, false);
	targetSlowApproachingDistance = ini.real(
		"target_slow_approaching_distance", targetSlowApproachingDistance, 0, 1e6);
	safetyFallback = ini.flag("safety_fallback", safetyFallback);
	ini.rejectUnknownKeys();
}

void CHolonomicVFH::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& section) const
{
	vfh.save(c, section, "fraction of ref_distance", false);
	lvf::common::writeOption(
		c, section, "target_slow_approaching_distance", targetSlowApproachingDistance,
		"slow down linearly when the target is nearer than this [fraction of ref_distance]");
	lvf::common::writeOption(
		c, section, "safety_fallback", safetyFallback,
		"no valley: retry with half the safety distance, then a quarter, before stopping (true/false)");
}

CHolonomicVFH::CHolonomicVFH(const mrpt::config::CConfigFileBase* ini)
	: CAbstractHolonomicReactiveMethod("CHolonomicVFH")
{
	if (ini) initialize(*ini);
}

void CHolonomicVFH::initialize(const mrpt::config::CConfigFileBase& ini)
{
	options.loadFromConfigFile(ini, getConfigFileSectionName());
	for (auto& e : m_engines) e.reset();
}

void CHolonomicVFH::saveConfigFile(mrpt::config::CConfigFileBase& c) const
{
	options.saveToConfigFile(c, getConfigFileSectionName());
}

VfhPlus& CHolonomicVFH::engine(size_t level)
{
	VfhParameters p = options.vfh;
	// Levels: the safety distance, half of it, a quarter (not none:
	// measured, dropping it brushed a floating box in the box room).
	p.safetyDistance = std::ldexp(p.safetyDistance, -int(level));
	auto& e = m_engines.at(level);
	if (!e || !(e->parameters() == p)) e = std::make_unique<VfhPlus>(p);
	return *e;
}

namespace
{
/** The log's per-PTG-direction curves (see CLogFileRecord_VFH.h), each
 * direction showing its VFH sector's values. */
void fillDirectionCurves(
	CLogFileRecord_VFH& log, const VfhPlus::Result& r, const VfhPlus& vfh, size_t directions,
	double previousDirection)
{
	const auto& s = vfh.sectors();
	const auto& p = vfh.parameters();
	const double worst = (p.mu1 + p.mu2 + p.mu3) * double(s.count()) / 2;
	const double previous = s.coordinate(previousDirection), heading = s.coordinate(0.0);
	std::vector<double> score(s.count(), 0.0);
	for (size_t k = 0; k < s.count(); k++)
		if (!r.masked[k] && worst > 0)
			score[k] = 1.0 - steeringCost(double(k), s, r.targetCoordinate, heading, previous, p) / worst;
	log.dirs_eval.assign(3, std::vector<double>(directions, 0.0));
	for (size_t i = 0; i < directions; i++)
	{
		const size_t k = s.sectorOf(-M_PI + (double(i) + 0.5) * 2 * M_PI / double(directions));
		log.dirs_eval[0][i] = 1.0 - std::min(1.0, r.primary[k] / p.tauHigh);
		log.dirs_eval[1][i] = r.masked[k] ? 0.0 : 1.0;
		log.dirs_eval[2][i] = score[k];
	}
}
}  // namespace

std::vector<ObstacleCell> CHolonomicVFH::tpObstacleCells(const NavInput& ni, double horizon)
{
	const size_t n = ni.obstacles.size();
	const double reach = std::min(1.0, horizon);
	std::vector<ObstacleCell> cells;
	cells.reserve(n);
	for (size_t i = 0; i < n; i++)
	{
		const double d = ni.obstacles[i] / ni.maxObstacleDist;
		if (!(d < reach)) continue;  // nothing seen along this trajectory
		const double a = -M_PI + (double(i) + 0.5) * 2 * M_PI / double(n);
		cells.push_back({d * std::cos(a), d * std::sin(a), 1.0});
	}
	return cells;
}

void CHolonomicVFH::navigate(const NavInput& ni, NavOutput& no)
{
	ASSERT_(!ni.obstacles.empty());
	ASSERT_(!ni.targets.empty());
	ASSERT_GT_(ni.maxObstacleDist, 0);
	// MRPT: "if many, last targets have higher priority".
	const mrpt::math::TPoint2D target = ni.targets.back() * (1.0 / ni.maxObstacleDist);
	// A TP-obstacle is a whole trajectory's free length, and one such cell
	// is denser than tau_high anywhere in the window: every direction with
	// anything before ref_distance would be blocked (measured: 68 of 72
	// sectors near a target in a 4 m room, the robot circling it). What lies
	// beyond the target along a trajectory does not stop the robot getting
	// there, so the window ends at the target (plus the safety distance, so
	// that an obstacle right at the target still counts).
	const double horizon = target.norm() + options.vfh.safetyDistance;
	const std::vector<ObstacleCell> cells = tpObstacleCells(ni, horizon);
	const double targetDirection = std::atan2(target.y, target.x);

	// In a gap narrower than the enlarged obstacles every sector is blocked
	// and VFH+ stops, for good: nothing changes while the robot stands
	// (measured: the box room, 72 of 72 sectors blocked between two boxes
	// the planned path passes). As the guidance's clearance, the safety
	// distance is then halved, and halved again; the TP distances remain
	// collision distances of the robot's shape, and MRPT's navigator slows
	// down near obstacles along the chosen trajectory.
	const size_t levels = options.safetyFallback ? kSafetyLevels : 1;
	VfhPlus* used = nullptr;
	VfhPlus::Result r;
	double previous = 0;
	for (size_t level = 0; level < levels && !r.found; level++)
	{
		used = &engine(level);
		previous = used->previousDirection().value_or(0.0);
		r = used->step(cells, targetDirection, 0.0);
	}
	const VfhPlus& vfh = *used;
	no.desiredDirection = r.found ? r.direction : 0.0;
	double speed = r.found ? r.speedFactor : 0.0;
	if (m_enableApproachTargetSlowDown && options.targetSlowApproachingDistance > 0)
		speed *= std::min(1.0, target.norm() / options.targetSlowApproachingDistance);
	no.desiredSpeed = ni.maxRobotSpeed * speed;

	auto log = CLogFileRecord_VFH::Create();
	log->primaryHistogram = r.primary;
	log->binaryHistogram = r.binary;
	log->maskedHistogram = r.masked;
	for (const auto& c : r.candidates)
	{
		log->candidateDirections.push_back(vfh.sectors().angle(c.coordinate));
		log->candidateCosts.push_back(c.cost);
	}
	log->targetDirection = targetDirection;
	log->chosenDirection = r.direction;
	log->found = r.found;
	log->speedFactor = r.speedFactor;
	log->tauLow = vfh.parameters().tauLow;
	log->tauHigh = vfh.parameters().tauHigh;
	fillDirectionCurves(*log, r, vfh, ni.obstacles.size(), previous);
	no.logRecord = log;
}

// Serialised as the INI text of its options: one format to keep in step.
uint8_t CHolonomicVFH::serializeGetVersion() const { return 0; }

void CHolonomicVFH::serializeTo(mrpt::serialization::CArchive& out) const
{
	mrpt::config::CConfigFileMemory cfg;
	options.saveToConfigFile(cfg, "CHolonomicVFH");
	out << cfg.getContent();
}

void CHolonomicVFH::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		{
			std::string text;
			in >> text;
			options.loadFromConfigFile(mrpt::config::CConfigFileMemory(text), "CHolonomicVFH");
			for (auto& e : m_engines) e.reset();
			break;
		}
		default: MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	}
}

}  // namespace lvf::vfh
