#pragma once
// A one-line progress bar for long batch runs, drawn only on an interactive
// terminal (never in CI logs or when output is redirected).

#include <cstddef>
#include <string>

namespace lvf::common
{
class ProgressBar
{
   public:
	ProgressBar(std::string label, size_t total);
	~ProgressBar();
	void update(size_t done);

   private:
	std::string m_label;
	size_t m_total;
	bool m_enabled;
	bool m_drawn = false;
};

}  // namespace lvf::common
