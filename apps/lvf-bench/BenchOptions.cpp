#include "BenchOptions.h"

#include <lvfusion/common/InputError.h>
#include <mrpt/system/string_utils.h>

#include <limits>
#include <stdexcept>

namespace lvf::bench
{
namespace
{
/** "SEED" or "FIRST-LAST" (0 <= FIRST <= LAST < 2^32). */
std::pair<uint32_t, uint32_t> parseSeedRange(const std::string& text)
{
	const auto dash = text.find('-');
	auto seed = [&](const std::string& part) {
		size_t used = 0;
		unsigned long long value = 0;
		try
		{
			if (part.empty() || part.front() == '-' || part.front() == '+') throw std::invalid_argument(part);
			value = std::stoull(part, &used);
		}
		catch (const std::exception&)
		{
			used = 0;
		}
		if (used != part.size() || used == 0 || value > std::numeric_limits<uint32_t>::max())
			throw lvf::common::InputError(
				"--random-rooms", text, "give a seed or FIRST-LAST, whole numbers from 0 to 4294967295");
		return static_cast<uint32_t>(value);
	};
	const auto range = dash == std::string::npos
		? std::pair{seed(text), seed(text)}
		: std::pair{seed(text.substr(0, dash)), seed(text.substr(dash + 1))};
	if (range.first > range.second)
		throw lvf::common::InputError("--random-rooms", text, "the first seed is after the last");
	return range;
}

/** A flag's value Google Benchmark reads as false. */
bool isFalse(const std::string& given)
{
	const std::string value = mrpt::system::lowerCase(given);
	return value == "false" || value == "f" || value == "no" || value == "n" || value == "off" || value == "0";
}
}  // namespace

OwnOptions takeOwnOptions(int& argc, char** argv)
{
	OwnOptions own;
	bool noTables = false;
	int kept = 1;
	for (int i = 1; i < argc; i++)
	{
		const std::string arg = argv[i];
		auto value = [&](const std::string& name) -> std::optional<std::string> {
			if (arg == name)
			{
				if (i + 1 >= argc) throw lvf::common::InputError(name, "", "needs a value");
				return std::string(argv[++i]);
			}
			if (arg.rfind(name + "=", 0) == 0) return arg.substr(name.size() + 1);
			return std::nullopt;
		};
		if (const auto dir = value("--middlebury"))
			own.middlebury = *dir;
		else if (const auto seeds = value("--random-rooms"))
			own.randomRooms = parseSeedRange(*seeds);
		else if (arg == "--no-tables")
			own.tables = false, noTables = true;
		else
		{
			// Listing runs nothing, the tables included (false as Google
			// Benchmark reads it: false, f, no, n, off, 0).
			const std::string list = "--benchmark_list_tests";
			if (arg == list || (arg.rfind(list + "=", 0) == 0 && !isFalse(arg.substr(list.size() + 1)))) own.tables = false;
			argv[kept++] = argv[i];
		}
	}
	argc = kept;
	if (noTables && own.randomRooms)
		throw lvf::common::InputError("--no-tables", "", "--random-rooms asks for a table: give one of them");
	return own;
}

void printOwnHelp(std::ostream& out)
{
	out << "lvf-bench [--middlebury DIR] [--random-rooms FIRST-LAST] [Google Benchmark's options below]\n"
		<< "  --middlebury DIR           Middlebury 2014 scenes for the real-image table (default "
		<< LVF_MIDDLEBURY_DIR << ")\n"
		<< "  --random-rooms FIRST-LAST  also compare the fusion with SGBM and BM on these seeded\n"
		<< "                             random rooms (lvf-simulate --random-world SEED's), time and\n"
		<< "                             accuracy over all their frames; e.g. 201-230\n"
		<< "  --no-tables                only the Google Benchmark cases (pick them with\n"
		<< "                             --benchmark_filter), not the stage, accuracy and real-image\n"
		<< "                             tables that follow them (a minute or more)\n"
		<< "  Each case runs for its own minimum time (1-2 s, MinTime in the code), whatever\n"
		<< "  --benchmark_min_time says.\n\n";
}

}  // namespace lvf::bench
