#include "SeededRooms.h"

#include "MethodRuns.h"
#include "SimulatedFrames.h"
#include "StageMedians.h"

#include <lvfusion/simulation/RandomWorld.h>

#include <iostream>
#include <map>

namespace lvf::bench
{
void printSeededRooms(uint32_t first, uint32_t last, int passes)
{
	using lvf::depth::DenseMatcher;
	const lvf::fusion::CLaserStereoFusion::TOptions options;  // lvf-fuse's defaults
	std::vector<SimulatedFrames> rooms;
	size_t frameCount = 0;
	for (uint64_t seed = first; seed <= last; seed++)  // 64 bits: no wrap when last is 2^32 - 1
	{
		rooms.emplace_back(lvf::simulation::generateRandomWorld(static_cast<uint32_t>(seed)));
		frameCount += rooms.back().frames.size();
	}

	StageMedians times;
	std::map<std::string, lvf::metrics::FusionScore> scores;
	for (int pass = 0; pass < passes; pass++)
		for (const auto& room : rooms)
		{
			// A fresh fusion per room, as lvf-fuse runs each room's log: the
			// point memory carries over the frames of one room only.
			lvf::fusion::CLaserStereoFusion fusion(options);
			for (size_t k = 0; k < room.frames.size(); k++)
			{
				const auto& frame = room.frames[k];
				const auto result = fusion.process(*frame.scan, *frame.stereo, "frame", frame.odometry);
				recordFusionTimes(times, kFusionName, result.times);
				const auto sgbm = room.dense(k, DenseMatcher::SemiGlobal, options, &times, kSgbmName);
				const auto bm = room.dense(k, DenseMatcher::Block, options, &times, kBmName);
				if (pass > 0) continue;
				scores[kFusionName].add(room.score(k, *result.fused, options));
				scores[kSgbmName].add(room.score(k, *sgbm, options));
				scores[kBmName].add(room.score(k, *bm, options));
				scores["laser alone"].add(room.score(k, *frame.scan, options));
			}
		}
	std::cout << "\nSeeded random rooms " << first << "-" << last << " (lvf-simulate --random-world SEED; "
			  << frameCount << " frames, " << rooms.front().left.front().cols << "x"
			  << rooms.front().left.front().rows << ", " << passes
			  << " passes, one thread), median time per frame and stage [ms]:\n";
	times.print(std::cout, kSgbmName);
	std::cout << "  against the simulator's truth scans:\n";
	for (const auto& [name, s] : scores) printScoreLine(std::cout, name, s);
}

}  // namespace lvf::bench
