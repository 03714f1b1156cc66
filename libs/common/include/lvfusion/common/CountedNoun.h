#pragma once
// Counts in the programs' summaries, in English: "1 frame", "3 frames".

#include <cstddef>
#include <string>

namespace lvf::common
{
/** `n` and `noun`, the noun plural (with an s) unless n is 1. */
inline std::string counted(size_t n, const std::string& noun)
{
	return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace lvf::common
