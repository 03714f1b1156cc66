#pragma once
// What every fuzz target shares: the bytes as a file (most readers take a
// path), and the contract under test. A reader given bad input must throw
// lvf::common::InputError, which the apps turn into one line and exit
// status 2 (AppMain.h); any other exception, a crash or a sanitizer report
// is a bug the fuzzer should stop on.

#include <lvfusion/common/InputError.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

namespace lvf::fuzz
{
/** A file holding `data`, one per process, rewritten for each input, in
 * TMPDIR (scripts/fuzz.sh points it into its build folder and empties it:
 * libFuzzer's -fork children end without a chance to remove their file). */
inline const std::string& inputFile(const uint8_t* data, size_t size, const char* suffix)
{
	static const std::string path =
		(std::filesystem::temp_directory_path() / ("lvf-fuzz-" + std::to_string(::getpid()) + suffix)).string();
	std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
	return path;
}

/** Runs `read`; InputError is the expected way to refuse. */
template <typename F>
void expectInputErrorOnly(F&& read)
{
	try
	{
		read();
	}
	catch (const lvf::common::InputError&)
	{
	}
	catch (const std::exception& e)
	{
		std::cerr << "not an InputError: " << e.what() << std::endl;
		std::abort();
	}
}
}  // namespace lvf::fuzz
