#include <lvfusion/common/RemovedIfKilled.h>

#include <csignal>
#include <filesystem>
#include <mutex>
#include <pthread.h>
#include <thread>
#include <vector>

namespace lvf::common
{
namespace
{
std::mutex foldersMutex;
std::vector<std::string> folders;
}  // namespace

void removeIfKilled(const std::string& folder)
{
	const std::lock_guard<std::mutex> lock(foldersMutex);
	folders.push_back(folder);
}

void removeFoldersWhenKilled()
{
	// A signal handler may neither allocate nor walk folders; a thread that
	// waits for the signal with sigwait may do both.
	sigset_t signals;
	sigemptyset(&signals);
	for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, s);
	if (pthread_sigmask(SIG_BLOCK, &signals, nullptr) != 0) return;
	std::thread([signals] {
		int received = 0;
		if (sigwait(&signals, &received) != 0) return;
		{
			const std::lock_guard<std::mutex> lock(foldersMutex);
			for (const auto& folder : folders)
			{
				std::error_code ignored;
				std::filesystem::remove_all(folder, ignored);
			}
		}
		// Die of the signal itself: status 128 + n to the shell.
		std::signal(received, SIG_DFL);
		pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
		std::raise(received);
	}).detach();
}

}  // namespace lvf::common
