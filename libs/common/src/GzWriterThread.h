#pragma once
// A gzip file compressed and written by a thread of its own: the caller
// hands over whole serialized entries and goes on while they are
// compressed. lvf-fuse's output repeats every input image (MRPT 2 stores
// them raw) and adds a colour picture a frame; compressing that took over
// half of a long run's time on the caller's thread.
//
// Entries are gathered until they reach a megabyte and written as one gzip
// member (GzipMemberFile.h): a member large enough that starting each one
// afresh costs nothing measurable (a long log's output, 174 MB: 94.7 MB in
// members, 95.2 MB as one stream from the igzip tool at the same level).
//
// The bytes reach the file in the order they were handed over. A write that
// fails (a full disk) is reported by the next write() or by close() as the
// one InputError line that names the file.

#include "GzipMemberFile.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lvf::common
{
class GzWriterThread
{
   public:
	/** Opens `path` for igzip's `level` (0 fastest .. 3 smallest; InputError if it
	 * cannot be opened); at most `maxQueuedBytes` wait for the thread at
	 * once (a larger entry goes alone): a few frames, so that a slow disk
	 * holds the caller back rather than memory filling up. */
	GzWriterThread(const std::string& path, int level, size_t maxQueuedBytes = size_t{4} << 20);
	/** Stops the thread and closes the file silently (close() reports). */
	~GzWriterThread();
	GzWriterThread(const GzWriterThread&) = delete;
	GzWriterThread& operator=(const GzWriterThread&) = delete;

	/** Queues bytes to follow those queued before; waits while the queue is
	 * full. Throws the InputError of an earlier write that failed. */
	void write(std::vector<uint8_t> bytes);
	/** Waits until every queued byte is written, closes the file, and throws
	 * the InputError naming it if any of it could not be written. */
	void close();

   private:
	void run();
	/** Lets the thread write what is queued, and waits for it. */
	void finish();
	const size_t m_maxQueuedBytes;
	GzipMemberFile m_file;	//!< the thread's, once it runs
	std::mutex m_mutex;
	std::condition_variable m_changed;
	std::deque<std::vector<uint8_t>> m_queue;
	size_t m_queuedBytes = 0;
	bool m_closing = false;
	std::exception_ptr m_error;
	std::thread m_thread;
};

}  // namespace lvf::common
