#pragma once
// The ends of file names: "run.rawlog", "x_truth_scans.csv", "NAME_fused".
// (C++17's std::string has no ends_with, nor MRPT's string utilities.)

#include <string>

namespace lvf::common
{
inline bool endsWith(const std::string& text, const std::string& suffix)
{
	return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/** Takes `suffix` off the end of `text` if it is there with something
 * before it; whether it did. */
inline bool stripSuffix(std::string& text, const std::string& suffix)
{
	const bool strip = text.size() > suffix.size() && endsWith(text, suffix);
	if (strip) text.resize(text.size() - suffix.size());
	return strip;
}

}  // namespace lvf::common
