#pragma once
// Folders a run makes for itself (the hidden staging folder of its outputs,
// a scratch cache) are removed when it ends, by the objects that made them.
// A run stopped by Ctrl-C or `kill` ends without unwinding, so those folders
// would stay: these remove them on SIGINT, SIGTERM and SIGHUP too.

#include <string>

namespace lvf::common
{
/** Remove `folder` (and all it holds) if the process is stopped by one of
 * those signals. Folders that are gone by then cost nothing. */
void removeIfKilled(const std::string& folder);

/** Takes SIGINT, SIGTERM and SIGHUP on a thread of its own, which removes
 * the folders above and then ends the process by the same signal (so the
 * shell sees it was interrupted). Call once, first thing in main, before
 * any other thread starts: the signals are blocked in every other thread
 * (they inherit the caller's mask; so would a child process, and the
 * programs start none). runApp does. */
void removeFoldersWhenKilled();

}  // namespace lvf::common
