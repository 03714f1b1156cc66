#pragma once
// The fusion's figures lvf-bench prints after its benchmarks
// (FusionBenchmarks.cpp), on the box room's frames, one thread.

namespace lvf::bench
{
/** Median time per frame of every stage of the fusion (and of variants with
 * one option flipped), SGBM and BM, over `passes` passes; each method in turn
 * per frame, so that a busy spell of the machine hits them alike. */
void printStageMedians(int passes);

/** Recall / phantom rate / range error of each method over all frames. */
void printAccuracy();
}  // namespace lvf::bench
