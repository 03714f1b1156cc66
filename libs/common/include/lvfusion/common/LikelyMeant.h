#pragma once
// "Did you mean ...?" for a misspelt key or section name: a typo in an INI
// or world file is the likeliest bad input, and the error that names it
// should also name what the user meant.

#include <string>
#include <vector>

namespace lvf::common
{
/** The name of `known` nearest `name` by edit distance (insertions,
 * deletions, substitutions and swaps of neighbouring characters, case
 * ignored), if it is at most two edits away and fewer than a third of
 * `name`'s characters; "" otherwise, or if two are as near. */
std::string likelyMeant(const std::string& name, const std::vector<std::string>& known);

/** " (did you mean 'X'?)" for likelyMeant's X, or "" if there is none: to
 * append to an "unknown key" message. */
std::string didYouMean(const std::string& name, const std::vector<std::string>& known);

}  // namespace lvf::common
