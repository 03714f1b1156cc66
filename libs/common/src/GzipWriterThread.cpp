#include "GzipWriterThread.h"

#include <lvfusion/common/InputError.h>
#include <mrpt/io/CFileGZOutputStream.h>

#include <stdexcept>

namespace lvf::common
{
GzipWriterThread::GzipWriterThread(const std::string& path, int level, size_t maxQueuedBytes)
	: m_path(path), m_maxQueuedBytes(maxQueuedBytes), m_out(std::make_unique<mrpt::io::CFileGZOutputStream>())
{
	if (!m_out->open(path, level)) throw InputError(path, "", "cannot open for writing");
	m_thread = std::thread([this] { run(); });
}

GzipWriterThread::~GzipWriterThread()
{
	try
	{
		close();
	}
	catch (...)
	{
		// close() reports it to a caller who asks; a destructor cannot.
	}
}

void GzipWriterThread::write(std::vector<uint8_t> bytes)
{
	std::unique_lock lock(m_mutex);
	// A buffer larger than the whole queue still goes, alone.
	m_changed.wait(lock, [&] { return m_error || m_queue.empty() || m_queuedBytes + bytes.size() <= m_maxQueuedBytes; });
	rethrowError();
	m_queuedBytes += bytes.size();
	m_queue.push_back(std::move(bytes));
	m_changed.notify_all();
}

void GzipWriterThread::close()
{
	{
		std::lock_guard lock(m_mutex);
		m_closing = true;
		m_changed.notify_all();
	}
	if (m_thread.joinable()) m_thread.join();
	if (m_out->fileOpenCorrectly()) m_out->close();
	std::lock_guard lock(m_mutex);
	rethrowError();
}

void GzipWriterThread::rethrowError()
{
	if (m_error) std::rethrow_exception(m_error);
}

void GzipWriterThread::run()
{
	for (;;)
	{
		std::vector<uint8_t> bytes;
		{
			std::unique_lock lock(m_mutex);
			m_changed.wait(lock, [&] { return m_closing || !m_queue.empty(); });
			if (m_queue.empty()) return;  // closing, and all written
			bytes = std::move(m_queue.front());
			m_queue.pop_front();
		}
		bool written = false;
		try
		{
			written = m_out->Write(bytes.data(), bytes.size()) == bytes.size();
		}
		catch (...)
		{
		}
		std::lock_guard lock(m_mutex);
		m_queuedBytes -= bytes.size();
		if (!written && !m_error)
		{
			// Nothing more is written: the rest would follow a gap.
			m_error = std::make_exception_ptr(InputError(m_path, "", "cannot be written (disk full?)"));
			m_queue.clear();
			m_queuedBytes = 0;
		}
		m_changed.notify_all();
		if (m_error) return;
	}
}

}  // namespace lvf::common
