#pragma once
// lvf-fuse's second pass over its input (RawlogFrames.h is the first): the
// log entry by entry; each frame handed to the fusion, in frame order, as
// soon as its scan and its stereo pair have been read; each entry handed on
// for writing, followed by the results of the frames that end at it, as
// soon as those are fused. Only the entries in between are held -- for a
// log recorded in time order, those within the pairing tolerance -- so a
// log of any length fuses in the memory of a few frames.

#include "RawlogFrames.h"

#include <mrpt/obs/CObservation.h>
#include <mrpt/serialization/CSerializable.h>

#include <functional>
#include <string>
#include <vector>

namespace lvf::apps
{
class FrameStream
{
   public:
	using Results = std::vector<mrpt::obs::CObservation::Ptr>;
	/** Fuses frame k, whose scan and stereo pair are read, and returns what
	 * to write after the frame's last entry. */
	using Fuse = std::function<Results(size_t k, const FusionFrame& frame)>;
	/** Writes one input entry as it was, then the results to follow it. */
	using Write = std::function<void(const mrpt::serialization::CSerializable& entry, const Results& after)>;

	/** `plan`: planRawlogFrames(path, ...), whose frames get their objects
	 * while they are fused. */
	FrameStream(std::string path, RawlogFrames& plan);

	/** Reads the log once more, calling `fuse` for every frame and `write`
	 * for every entry, in file order. External images are pointed at their
	 * files (ExternalImages.h) as their entries are read. Throws
	 * InputError if the file no longer matches the plan. */
	void run(const Fuse& fuse, const Write& write);

	/** Images of the log kept as files, and the folder they are in. */
	size_t externalImages() const { return m_externalImages; }
	const std::string& externalImagesFolder() const { return m_imagesFolder; }
	/** The most entries held at once (read, not yet written). */
	size_t entriesHeldAtMost() const { return m_heldAtMost; }

   private:
	std::string m_path, m_imagesFolder;
	RawlogFrames& m_plan;
	size_t m_externalImages = 0, m_heldAtMost = 0;
};

}  // namespace lvf::apps
