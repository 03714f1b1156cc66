// fuse_rawlog IN.rawlog [FUSION.ini]: lvfusion's laser-stereo fusion in a
// program of your own. Reads a rawlog with MRPT's own reader (either layout),
// pairs each stereo pair with the laser scan taken with it (the latest, within
// 50 ms; lvf-fuse pairs more carefully), and prints per
// frame how many bearings of the fused scan are nearer than the laser's: the
// obstacles only the cameras saw. The fused scan is an ordinary
// CObservation2DRangeScan: insert it into a grid, hand it to a reactive
// navigator, or write it to a rawlog as lvf-fuse does.

#include <lvfusion/common/ProcessMemory.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

int main(int argc, char** argv)
{
	if (argc < 2 || argc > 3)
	{
		std::cerr << "usage: fuse_rawlog IN.rawlog [FUSION.ini]\n";
		return 2;
	}
	// Frame after frame, keep the fusion's large buffers in the heap instead
	// of mapping them afresh: without it the first frames take 4-5 times as
	// long (ProcessMemory.h). A process-wide setting, so the program's call.
	lvf::common::retainLargeAllocations();
	try
	{
		// The built-in defaults are share/lvfusion/config/fusion.ini's; a
		// file given overrides the keys it holds, section by section.
		lvf::fusion::CLaserStereoFusion::TOptions options;
		if (argc == 3) options.loadFromConfigFile(mrpt::config::CConfigFile(argv[2]), "CLaserStereoFusion");
		lvf::fusion::CLaserStereoFusion fusion(options);

		if (!std::filesystem::is_regular_file(argv[1]))
			throw std::runtime_error(std::string(argv[1]) + ": no such rawlog");
		mrpt::io::CFileGZInputStream file(argv[1]);
		auto archive = mrpt::serialization::archiveFrom(file);
		mrpt::obs::CActionCollection::Ptr actions;
		mrpt::obs::CSensoryFrame::Ptr frame;
		mrpt::obs::CObservation::Ptr single;
		size_t entry = 0, fused = 0;
		mrpt::obs::CObservation2DRangeScan::Ptr lastScan;
		// The robot's odometry lets the fusion keep earlier frames' visual
		// points where the cameras cannot look now ([VisualPointMemory]);
		// without it each frame stands alone.
		std::optional<mrpt::poses::CPose2D> odometry;
		auto take = [&](const mrpt::obs::CObservation::Ptr& obs) {
			if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs)) odometry = odo->odometry;
			if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs)) lastScan = scan;
			auto stereo = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(obs);
			if (!stereo || !lastScan ||
				std::abs(mrpt::system::timeDifference(lastScan->timestamp, stereo->timestamp)) > 0.05)
				return;
			const auto result = fusion.process(*lastScan, *stereo, "entry " + std::to_string(entry), odometry);
			std::cout << "frame " << fused++ << ": " << result.shortenedBearings(*lastScan) << " of "
					  << lastScan->getScanSize() << " bearings nearer than the laser, "
					  << result.search.points.size() << " visual points, " << result.times.total() << " ms\n";
		};
		while (mrpt::obs::CRawlog::getActionObservationPairOrObservation(archive, actions, frame, single, entry))
		{
			// Sensory-frame layout: odometry comes as increments in actions.
			if (actions)
				if (const auto move = actions->getBestMovementEstimation())
					odometry = odometry.value_or(mrpt::poses::CPose2D()) + move->poseChange->getMeanVal();
			if (frame)
				for (const auto& obs : *frame) take(obs);
			if (single) take(single);
		}
		std::cout << fused << " frames fused\n";
	}
	catch (const std::exception& e)
	{
		// lvfusion's bad-input errors (lvf::common::InputError) say which
		// file, record and field; MRPT's say what it could not read.
		std::cerr << "fuse_rawlog: " << e.what() << "\n";
		return 2;
	}
	return 0;
}
