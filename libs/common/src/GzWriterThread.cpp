#include "GzWriterThread.h"

#include <libdeflate.h>

#include <stdexcept>

namespace lvf::common
{
namespace
{
/** Bytes gathered into one gzip member (fewer in the last). */
constexpr size_t kMemberBytes = size_t{1} << 20;
}  // namespace

void GzWriterThread::FreeCompressor::operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }

GzWriterThread::GzWriterThread(const std::string& path, int level, size_t maxQueuedBytes)
	: m_maxQueuedBytes(maxQueuedBytes),
	  m_file(path, std::ios::binary),
	  m_compressor(libdeflate_alloc_compressor(level))
{
	if (!m_compressor) throw std::invalid_argument("GzWriterThread: compression level " + std::to_string(level));
	m_thread = std::thread([this] { run(); });
}

GzWriterThread::~GzWriterThread() { finish(); }	// ~OutputFile closes silently

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

void GzWriterThread::writeMember(const std::vector<uint8_t>& bytes)
{
	m_compressed.resize(libdeflate_gzip_compress_bound(m_compressor.get(), bytes.size()));
	const size_t size =
		libdeflate_gzip_compress(m_compressor.get(), bytes.data(), bytes.size(), m_compressed.data(), m_compressed.size());
	// (The bound holds by libdeflate's contract; 0 would mean it did not.)
	if (size == 0) throw std::logic_error("libdeflate: a gzip member larger than its bound");
	m_file.write(reinterpret_cast<const char*>(m_compressed.data()), static_cast<std::streamsize>(size));
	requireWritten(!m_file.fail(), m_file.path());
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
				writeMember(member);
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
