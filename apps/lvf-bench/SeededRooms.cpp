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
	// Each method over every frame in turn, pass by pass, as each runs on a
	// robot and as the Google Benchmark cases run: each is timed in its own
	// steady state. Run frame by frame in turn, SGBM's and BM's passes over
	// tens of MB left the fusion's images out of the cache and its memory
	// handed back to the kernel: the fusion took 7.7-7.8 ms a frame on rooms
	// 301-340 there against 6.7 ms here, SGBM 64-65 ms against 66-67 ms
	// (measurements.md, session 54).
	for (int pass = 0; pass < passes; pass++)
	{
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
				if (pass > 0) continue;
				scores[kFusionName].add(room.score(k, *result.fused, options));
				scores["laser alone"].add(room.score(k, *frame.scan, options));
			}
		}
		for (const auto& [matcher, name] : kDenseMethods)
			for (const auto& room : rooms)
				for (size_t k = 0; k < room.frames.size(); k++)
				{
					const auto scan = room.dense(k, matcher, options, &times, name);
					if (pass == 0) scores[name].add(room.score(k, *scan, options));
				}
	}
	std::cout << "\nSeeded random rooms " << first << "-" << last << " (lvf-simulate --random-world SEED; "
			  << frameCount << " frames, " << rooms.front().left.front().cols << "x"
			  << rooms.front().left.front().rows << ", " << passes
			  << " passes, one thread, each method over all frames in turn), median time per frame and stage [ms]:\n";
	times.print(std::cout, kSgbmName);
	std::cout << "  against the simulator's truth scans:\n";
	for (const auto& [name, s] : scores) printScoreLine(std::cout, name, s);
}

}  // namespace lvf::bench
