#include <lvfusion/vfh/BinaryHistogram.h>

namespace lvf::vfh
{
const std::vector<uint8_t>& BinaryHistogram::update(const std::vector<double>& density)
{
	if (m_blocked.size() != density.size()) m_blocked.assign(density.size(), 0);
	for (size_t k = 0; k < density.size(); k++)
	{
		if (density[k] > m_tauHigh) m_blocked[k] = 1;
		else if (density[k] < m_tauLow)
			m_blocked[k] = 0;
	}
	return m_blocked;
}

}  // namespace lvf::vfh
