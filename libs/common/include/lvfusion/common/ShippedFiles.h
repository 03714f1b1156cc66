#pragma once
// The files lvfusion ships (share/lvfusion's configurations and worlds, the
// rawlog samples), found where the program runs from: installed, they lie in
// <prefix>/share/lvfusion beside <prefix>/bin; in a build tree, in the source
// tree the build came from.

#include <string>

namespace lvf::common
{
/** `<prefix>/share/lvfusion/<installed>` when the running program lies in
 * `<prefix>/bin` and that file exists there (the install's own bin/ and
 * share/ directories, GNUInstallDirs'); otherwise `inSourceTree`. */
std::string shippedFile(const std::string& installed, const std::string& inSourceTree);
}  // namespace lvf::common
