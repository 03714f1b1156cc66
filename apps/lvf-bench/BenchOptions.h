#pragma once
// lvf-bench's own command-line options, taken out of argv before Google
// Benchmark reads the rest (it refuses what it does not know).

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <utility>

namespace lvf::bench
{
struct OwnOptions
{
	std::string middlebury = LVF_MIDDLEBURY_DIR;  //!< folder of Middlebury scenes
	std::optional<std::pair<uint32_t, uint32_t>> randomRooms;  //!< seeds, first and last
};

/** Takes `--middlebury DIR` and `--random-rooms FIRST-LAST` (each also as
 * `--name=VALUE`) out of argv, leaving Google Benchmark's options; a bad
 * value is an InputError naming the option. */
OwnOptions takeOwnOptions(int& argc, char** argv);

/** The usage lines of these options, printed before Google Benchmark's. */
void printOwnHelp(std::ostream& out);
}  // namespace lvf::bench
