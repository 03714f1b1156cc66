#include "GzWriterThread.h"

#include <lvfusion/common/WrittenFiles.h>

namespace lvf::common
{
GzWriterThread::GzWriterThread(const std::string& path, int level, size_t maxQueuedBytes)
	: m_path(path), m_maxQueuedBytes(maxQueuedBytes), m_file(path, level), m_thread([this] { run(); })
{
}

GzWriterThread::~GzWriterThread() { finish(); }	// ~GzOutputFile closes silently

void GzWriterThread::write(std::vector<uint8_t> bytes)
{
	std::unique_lock lock(m_mutex);
	m_changed.wait(lock, [&] {
		return m_error || m_queue.empty() || m_queuedBytes + bytes.size() <= m_maxQueuedBytes;
	});
	if (m_error) std::rethrow_exception(m_error);
	m_queuedBytes += bytes.size();
	m_queue.push_back(std::move(bytes));
	m_changed.notify_all();
}

void GzWriterThread::close()
{
	finish();
	if (m_error) std::rethrow_exception(m_error);
	m_file.close();
}

void GzWriterThread::finish()
{
	{
		std::lock_guard lock(m_mutex);
		m_closing = true;
		m_changed.notify_all();
	}
	if (m_thread.joinable()) m_thread.join();
}

void GzWriterThread::run()
{
	for (;;)
	{
		std::vector<uint8_t> bytes;
		{
			std::unique_lock lock(m_mutex);
			m_changed.wait(lock, [&] { return m_closing || !m_queue.empty(); });
			if (m_queue.empty()) return;  // closing, and everything written
			bytes = std::move(m_queue.front());
			m_queue.pop_front();
		}
		std::exception_ptr error;
		try
		{
			requireWritten(m_file.Write(bytes.data(), bytes.size()) == bytes.size(), m_path);
		}
		catch (...)
		{
			error = std::current_exception();
		}
		std::lock_guard lock(m_mutex);
		m_queuedBytes -= bytes.size();
		if (error)
		{
			// Nothing more goes to the file: the rest would follow a gap.
			m_error = error;
			m_queue.clear();
			m_queuedBytes = 0;
		}
		m_changed.notify_all();
		if (m_error) return;
	}
}

}  // namespace lvf::common
