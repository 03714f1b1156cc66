#pragma once
// lvf-bench on seeded random rooms (`--random-rooms FIRST-LAST`): the rooms
// lvf-simulate --random-world SEED makes, each through the fusion and the two
// dense matchers, so that the box room's comparison can be repeated on rooms
// no setting was chosen on: time per frame and stage, and recall / phantom
// rate / range error of each over all the rooms' frames.

#include <cstdint>

namespace lvf::bench
{
/** Seeds `first` to `last` (inclusive), `passes` timed passes over their
 * frames, one thread; the scores are taken on the first pass. */
void printSeededRooms(uint32_t first, uint32_t last, int passes);
}  // namespace lvf::bench
