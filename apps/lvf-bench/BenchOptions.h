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
	/** The stage, accuracy and real-image tables after the benchmarks;
	 * off with --no-tables (one micro-benchmark, quickly) and with Google
	 * Benchmark's --benchmark_list_tests (which runs nothing). */
	bool tables = true;
};

/** Takes `--middlebury DIR`, `--random-rooms FIRST-LAST` (each also as
 * `--name=VALUE`) and `--no-tables` out of argv, leaving Google Benchmark's
 * options (and notes --benchmark_list_tests among them); a bad
 * value is an InputError naming the option. */
OwnOptions takeOwnOptions(int& argc, char** argv);

/** The usage lines of these options, printed before Google Benchmark's. */
void printOwnHelp(std::ostream& out);
}  // namespace lvf::bench
