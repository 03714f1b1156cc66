#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/ProgressBar.h>
#include <mrpt/system/progress.h>

#include <cstdio>

namespace lvf::common
{
ProgressBar::ProgressBar(std::string label, size_t total)
	: m_label(std::move(label)), m_total(total), m_enabled(interactiveTerminal())
{
}

ProgressBar::~ProgressBar()
{
	if (m_drawn) std::fputc('\n', stdout);
}

void ProgressBar::update(size_t done)
{
	if (!m_enabled || m_total == 0) return;
	const double ratio = static_cast<double>(done) / static_cast<double>(m_total);
	std::printf(
		"\r%s %s %zu/%zu", m_label.c_str(),
		mrpt::system::progress(ratio, 30).c_str(), done, m_total);
	std::fflush(stdout);
	m_drawn = true;
}

}  // namespace lvf::common
