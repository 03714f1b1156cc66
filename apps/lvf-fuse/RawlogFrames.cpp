#include "RawlogFrames.h"

#include <lvfusion/common/RawlogReader.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ObservationLabels.h>
#include <lvfusion/common/OdometryReadings.h>
#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

namespace lvf::apps
{
namespace
{
struct Stamped
{
	ObservationPlace at;
	double t;
	mrpt::Clock::time_point stamp;
	std::string label;
	size_t rays = 0;  //!< a scan's
};

/** The observations of the chosen sensor (all of them if the log has only
 * one); `kind` and `option` name them in the errors. */
std::vector<Stamped> ofSensor(
	const std::vector<Stamped>& all, const std::string& chosen, const std::string& path, const std::string& kind,
	const std::string& option)
{
	std::set<std::string> labels;
	for (const auto& o : all) labels.insert(o.label);
	std::string found;
	for (const auto& label : labels) found += (found.empty() ? "" : ", ") + (label.empty() ? "(no label)" : label);
	if (chosen.empty())
	{
		if (labels.size() > 1)
			throw lvf::common::InputError(path, "", mrpt::format(
				"%s from %zu sensors (%s): choose one with %s", kind.c_str(), labels.size(), found.c_str(),
				option.c_str()));
		return all;
	}
	if (!labels.count(chosen))
		throw lvf::common::InputError(path, "", mrpt::format(
			"no %s labelled '%s' (%s)", kind.c_str(), chosen.c_str(),
			labels.empty() ? "there are none" : ("labels: " + found).c_str()));
	std::vector<Stamped> out;
	for (const auto& o : all)
		if (o.label == chosen) out.push_back(o);
	return out;
}
}  // namespace

RawlogFrames planRawlogFrames(const std::string& path, double maxTimeDiff, const SensorLabels& labels)
{
	RawlogFrames out;
	std::vector<Stamped> allScans, allStereos;
	lvf::common::OdometryReadings odometry;
	mrpt::poses::CPose2D dead;	// accumulated action increments (sf layout)
	std::vector<mrpt::poses::CPose2D> poseAtEntry;
	auto take = [&](ObservationPlace at, const mrpt::obs::CObservation::Ptr& o) {
		const double t = mrpt::Clock::toDouble(o->timestamp);
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o);
			s && s->sensorLabel != lvf::common::kFusedScanLabel)
			allScans.push_back({at, t, o->timestamp, o->sensorLabel, s->getScanSize()});
		else if (std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o))
			allStereos.push_back({at, t, o->timestamp, o->sensorLabel});
		else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o))
			odometry.add(odo->timestamp, odo->odometry);
	};
	lvf::common::RawlogReader reader(path);
	for (size_t i = 0; auto entry = reader.next(); i++)
	{
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
		{
			size_t slot = 0;
			for (const auto& o : *sf) take({i, slot++}, o);
		}
		else if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(entry))
			take({i, 0}, o);
		poseAtEntry.push_back(dead);
	}
	out.entries = reader.count();
	if (!odometry.empty()) out.hasOdometry = true;
	const auto scans = ofSensor(allScans, labels.laser, path, "2D scans", "--laser-label");
	auto stereos = ofSensor(allStereos, labels.stereo, path, "stereo pairs", "--stereo-label");
	out.scans = scans.size();
	out.stereoPairs = stereos.size();

	// In time order (stable: the first in the file of equal times), so that
	// a scan's nearest pair is a binary search away (a real log holds tens of
	// thousands).
	auto byTime = [](const auto& a, const auto& b) { return a.t < b.t; };
	std::stable_sort(stereos.begin(), stereos.end(), byTime);
	for (const auto& s : scans)
	{
		// The pair nearest in time; of two as near, the earlier.
		const Stamped* best = nullptr;
		auto after = std::lower_bound(stereos.begin(), stereos.end(), s.t, [](const Stamped& st, double t) { return st.t < t; });
		if (after != stereos.end()) best = &*after;
		if (after != stereos.begin() && (!best || s.t - std::prev(after)->t <= best->t - s.t)) best = &*std::prev(after);
		if (!best || std::abs(best->t - s.t) > maxTimeDiff)
		{
			out.unpairedScans++;
			continue;
		}
		FusionFrame f;
		f.scanAt = s.at;
		f.stereoAt = best->at;
		f.scanTime = s.t;
		f.scanBearings = s.rays;
		f.odometry = odometry.empty() ? poseAtEntry[s.at.entry] : odometry.poseAt(s.stamp);
		out.frames.push_back(f);
	}
	return out;
}

}  // namespace lvf::apps
