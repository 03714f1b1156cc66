#pragma once
// Per-frame image buffers (integral images, float copies of a 640x480 pair:
// a few MB each) are above glibc's mmap threshold, so each frame maps them
// afresh and unmaps them again, and every first touch of their pages faults.
// Measured on the box room (lvf-bench stage medians): the grid evaluation
// took 4.0-7.7 ms per frame that way and 2.9 ms with the memory kept.
// Programs that process frame after frame call this once at start; a
// library has no business setting it for its host process.

namespace lvf::common
{
/** Asks the C library to serve and keep large blocks from its heap. */
void retainLargeAllocations();
}  // namespace lvf::common
