#include "RawlogFrames.h"

#include <lvfusion/common/RawlogReader.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <cmath>

namespace lvf::apps
{
namespace
{
struct Stamped
{
	size_t entry;
	double t;
	mrpt::obs::CObservation::Ptr obs;
};
}  // namespace

RawlogFrames loadRawlogFrames(const std::string& path, double maxTimeDiff)
{
	RawlogFrames out;
	out.entries = lvf::common::readRawlogEntries(path);

	std::vector<Stamped> scans, stereos;
	std::vector<std::pair<double, mrpt::poses::CPose2D>> odometry;	// time, pose
	mrpt::poses::CPose2D dead;	// accumulated action increments (sf layout)
	std::vector<mrpt::poses::CPose2D> poseAtEntry(out.entries.size());
	auto take = [&](size_t entry, const mrpt::obs::CObservation::Ptr& o) {
		const double t = mrpt::Clock::toDouble(o->timestamp);
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o);
			s && s->sensorLabel != "FUSED")
			scans.push_back({entry, t, o});
		else if (std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o))
			stereos.push_back({entry, t, o});
		else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o))
			odometry.emplace_back(t, odo->odometry);
	};
	for (size_t i = 0; i < out.entries.size(); i++)
	{
		const auto& entry = out.entries[i];
		if (auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(entry))
		{
			out.sensoryFrames = true;
			if (auto move = actions->getBestMovementEstimation())
			{
				dead = dead + move->poseChange->getMeanVal();
				out.hasOdometry = true;
			}
		}
		else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(entry))
			for (const auto& o : *sf) take(i, o);
		else if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(entry))
			take(i, o);
		poseAtEntry[i] = dead;
	}
	if (!odometry.empty()) out.hasOdometry = true;
	out.scans = scans.size();
	out.stereoPairs = stereos.size();

	for (const auto& s : scans)
	{
		const Stamped* best = nullptr;
		for (const auto& st : stereos)
			if (!best || std::abs(st.t - s.t) < std::abs(best->t - s.t)) best = &st;
		if (!best || std::abs(best->t - s.t) > maxTimeDiff)
		{
			out.unpairedScans++;
			continue;
		}
		FusionFrame f;
		f.scanEntry = s.entry;
		f.stereoEntry = best->entry;
		f.scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(s.obs);
		f.stereo = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(best->obs);
		f.stereoDelay = best->t - s.t;
		f.odometry = poseAtEntry[s.entry];
		for (const auto& [t, pose] : odometry)	// latest reading not after the scan
			if (t <= s.t + 1e-6) f.odometry = pose;
		out.frames.push_back(f);
	}
	return out;
}

}  // namespace lvf::apps
