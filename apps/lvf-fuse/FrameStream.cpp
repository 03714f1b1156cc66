#include "FrameStream.h"

#include <lvfusion/common/ExternalImages.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogReader.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <algorithm>
#include <deque>
#include <map>

namespace lvf::apps
{
namespace
{
/** The observation at `slot` of an entry (a sensory frame's, or the entry). */
mrpt::obs::CObservation::Ptr observationAt(const mrpt::serialization::CSerializable::Ptr& entry, size_t slot)
{
	if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(entry))
		return slot < sf->size() ? sf->getObservationByIndex(slot) : nullptr;
	return std::dynamic_pointer_cast<mrpt::obs::CObservation>(entry);
}

lvf::common::InputError changed(const std::string& path)
{
	return lvf::common::InputError(path, "", "the file changed while it was being read");
}
}  // namespace

FrameStream::FrameStream(std::string path, RawlogFrames& plan)
	: m_path(std::move(path)), m_imagesFolder(lvf::common::externalImagesDirectory(m_path)), m_plan(plan)
{
}

void FrameStream::run(const Fuse& fuse, const Write& write)
{
	auto& frames = m_plan.frames;
	// Per entry: the frames that read an observation of it, and how many
	// frames ending at it are not fused yet (it is written after them).
	std::vector<std::vector<size_t>> readers(m_plan.entries);
	std::vector<size_t> unfusedEndingAt(m_plan.entries, 0);
	for (size_t k = 0; k < frames.size(); k++)
	{
		readers[frames[k].scanAt.entry].push_back(k);
		if (frames[k].stereoAt.entry != frames[k].scanAt.entry) readers[frames[k].stereoAt.entry].push_back(k);
		unfusedEndingAt[frames[k].lastEntry()]++;
	}
	std::map<size_t, Results> resultsAfter;	 // by entry, for entries not written yet
	std::deque<std::pair<size_t, mrpt::serialization::CSerializable::Ptr>> unwritten;
	size_t nextFrame = 0;
	lvf::common::RawlogReader reader(m_path);
	for (size_t i = 0; auto entry = reader.next(); i++)
	{
		if (i >= m_plan.entries) throw changed(m_path);
		m_externalImages += lvf::common::anchorExternalImages(entry, m_imagesFolder);
		for (size_t k : readers[i])
		{
			auto& f = frames[k];
			if (f.scanAt.entry == i)
				f.scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(observationAt(entry, f.scanAt.slot));
			if (f.stereoAt.entry == i)
				f.stereo = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(
					observationAt(entry, f.stereoAt.slot));
			if ((f.scanAt.entry == i && !f.scan) || (f.stereoAt.entry == i && !f.stereo)) throw changed(m_path);
		}
		unwritten.emplace_back(i, std::move(entry));
		m_heldAtMost = std::max(m_heldAtMost, unwritten.size());
		// Frames in order: each one's grids and memory build on the last's.
		while (nextFrame < frames.size() && frames[nextFrame].scan && frames[nextFrame].stereo)
		{
			auto& f = frames[nextFrame];
			const Results results = fuse(nextFrame, f);
			auto& after = resultsAfter[f.lastEntry()];
			after.insert(after.end(), results.begin(), results.end());
			unfusedEndingAt[f.lastEntry()]--;
			f.scan.reset(), f.stereo.reset();
			nextFrame++;
		}
		while (!unwritten.empty() && unfusedEndingAt[unwritten.front().first] == 0)
		{
			const auto& [e, object] = unwritten.front();
			const auto after = resultsAfter.find(e);
			write(*object, after != resultsAfter.end() ? after->second : Results{});
			if (after != resultsAfter.end()) resultsAfter.erase(after);
			unwritten.pop_front();
		}
	}
	if (reader.count() != m_plan.entries || nextFrame != frames.size()) throw changed(m_path);
}

}  // namespace lvf::apps
