#pragma once
// Folders a run makes for itself (the hidden staging folder of its outputs,
// a scratch cache) are removed when it ends, by the objects that made them.
// A run stopped by Ctrl-C or `kill` ends without unwinding, so those folders
// would stay: these remove them on SIGINT, SIGTERM and SIGHUP too.

#include <mutex>
#include <string>

namespace lvf::common
{
/** Remove `folder` (and all it holds) if the process is stopped by one of
 * those signals; register it before making it. */
void removeOnSignal(const std::string& folder);
/** No longer: the folder is gone (its owner removed it or moved it into
 * place), and another process may make one of that name. */
void keepOnSignal(const std::string& folder);

/** Held while outputs are moved into place: a signal then waits until they
 * all are, so that a run is never left half moved. */
std::unique_lock<std::mutex> holdOffSignalCleanup();

/** Takes SIGINT, SIGTERM and SIGHUP on a thread of its own, which removes
 * the folders above and then ends the process by the same signal (so the
 * shell sees it was interrupted). A signal the process was started with
 * ignored (`nohup`, a script's background job) stays ignored. Call first
 * thing in main, before any other thread starts: the signals are blocked in
 * every other thread (they inherit the caller's mask; so would a child
 * process, and the programs start none). runApp does; later calls do
 * nothing. */
void installSignalCleanup();

}  // namespace lvf::common
