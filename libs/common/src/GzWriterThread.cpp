#include "GzWriterThread.h"

namespace lvf::common
{
namespace
{
/** Bytes gathered into one gzip member (fewer in the last). */
constexpr size_t kMemberBytes = size_t{1} << 20;
}  // namespace

GzWriterThread::GzWriterThread(const std::string& path, int level, size_t maxQueuedBytes)
	: m_maxQueuedBytes(maxQueuedBytes), m_file(path, level)
{
	m_thread = std::thread([this] { run(); });
}

GzWriterThread::~GzWriterThread() { finish(); }	// ~GzipMemberFile closes silently

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
	std::vector<uint8_t> member;  // entries gathered towards kMemberBytes
	for (;;)
	{
		std::vector<uint8_t> bytes;
		size_t taken = 0;
		bool last = false;
		{
			std::unique_lock lock(m_mutex);
			m_changed.wait(lock, [&] { return m_closing || !m_queue.empty(); });
			if (m_queue.empty()) last = true;  // closing, and everything handed over
			else
			{
				bytes = std::move(m_queue.front());
				m_queue.pop_front();
				taken = bytes.size();
			}
		}
		std::exception_ptr error;
		try
		{
			if (member.empty()) member.swap(bytes);
			else member.insert(member.end(), bytes.begin(), bytes.end());
			if (!member.empty() && (member.size() >= kMemberBytes || last))
			{
				m_file.writeMember(member);
				member.clear();
			}
		}
		catch (...)
		{
			error = std::current_exception();
		}
		std::lock_guard lock(m_mutex);
		m_queuedBytes -= taken;
		if (error)
		{
			// Nothing more goes to the file: the rest would follow a gap.
			m_error = error;
			m_queue.clear();
			m_queuedBytes = 0;
		}
		m_changed.notify_all();
		if (m_error || last) return;
	}
}

}  // namespace lvf::common
