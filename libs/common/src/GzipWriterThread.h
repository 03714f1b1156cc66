#pragma once
// A gzip file written by a thread of its own. Deflate, even at level 1, took
// as long as the fusion itself in lvf-fuse (its output repeats every input
// image, raw as MRPT 2 serializes them, and adds a colour picture a frame):
// on a thread of its own it runs while the next frame is fused.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace mrpt::io
{
class CFileGZOutputStream;
}

namespace lvf::common
{
class GzipWriterThread
{
   public:
	/** Opens `path` for writing at gzip `level` (InputError if it cannot);
	 * at most `maxQueuedBytes` wait to be written at once. */
	GzipWriterThread(const std::string& path, int level, size_t maxQueuedBytes = size_t{64} << 20);
	/** Writes what is still queued and closes the file (errors ignored:
	 * close() reports them). */
	~GzipWriterThread();

	/** Queues bytes to follow those queued before; waits while the queue is
	 * full. Throws what went wrong writing earlier bytes, if anything did. */
	void write(std::vector<uint8_t> bytes);
	/** Waits until every queued byte is written, closes the file, and throws
	 * what went wrong, if anything did. */
	void close();

   private:
	void run();
	void rethrowError();

	const std::string m_path;
	const size_t m_maxQueuedBytes;
	std::unique_ptr<mrpt::io::CFileGZOutputStream> m_out;
	std::mutex m_mutex;
	std::condition_variable m_changed;
	std::deque<std::vector<uint8_t>> m_queue;
	size_t m_queuedBytes = 0;
	bool m_closing = false;
	std::exception_ptr m_error;
	std::thread m_thread;
};

}  // namespace lvf::common
