#include <lvfusion/common/SignalCleanup.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <pthread.h>
#include <thread>
#include <vector>

namespace lvf::common
{
namespace
{
/** Never destroyed: the signal thread may use it while the process exits. */
struct Registry
{
	std::mutex foldersMutex;
	std::vector<std::string> folders;
	std::mutex movingMutex;	 //!< held by holdOffSignalCleanup
};
Registry& registry()
{
	static Registry* r = new Registry;
	return *r;
}

void removeAll(const std::string& folder)
{
	// The main thread may still be writing into it: try a few times.
	for (int attempt = 0; attempt < 10 && std::filesystem::exists(folder); attempt++)
	{
		std::error_code ignored;
		std::filesystem::remove_all(folder, ignored);
	}
}
}  // namespace

void removeOnSignal(const std::string& folder)
{
	Registry& r = registry();
	const std::lock_guard<std::mutex> lock(r.foldersMutex);
	r.folders.push_back(folder);
}

void keepOnSignal(const std::string& folder)
{
	Registry& r = registry();
	const std::lock_guard<std::mutex> lock(r.foldersMutex);
	r.folders.erase(std::remove(r.folders.begin(), r.folders.end(), folder), r.folders.end());
}

std::unique_lock<std::mutex> holdOffSignalCleanup() { return std::unique_lock<std::mutex>(registry().movingMutex); }

void installSignalCleanup()
{
	static std::once_flag once;
	std::call_once(once, [] {
		// A signal handler may neither allocate nor walk folders; a thread
		// that waits for the signal with sigwait may do both.
		sigset_t signals;
		sigemptyset(&signals);
		for (const int s : {SIGINT, SIGTERM, SIGHUP})
		{
			struct sigaction current = {};
			if (sigaction(s, nullptr, &current) == 0 && current.sa_handler != SIG_IGN) sigaddset(&signals, s);
		}
		sigset_t before;
		if (pthread_sigmask(SIG_BLOCK, &signals, &before) != 0) return;
		try
		{
			std::thread([signals] {
				int received = 0;
				if (sigwait(&signals, &received) != 0) return;
				Registry& r = registry();
				// Never released: the process ends below.
				r.movingMutex.lock();
				r.foldersMutex.lock();
				for (const auto& folder : r.folders) removeAll(folder);
				// Die of the signal itself: status 128 + n to the shell.
				std::signal(received, SIG_DFL);
				pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
				std::raise(received);
			}).detach();
		}
		catch (const std::system_error&)
		{
			pthread_sigmask(SIG_SETMASK, &before, nullptr);	 // no thread: the signals as they were
		}
	});
}

}  // namespace lvf::common
