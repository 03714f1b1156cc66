#pragma once
// VFH+'s binary polar histogram (Ulrich & Borenstein 1998, §2.2): a sector is
// blocked (1) when its density exceeds tau_high, free (0) below tau_low, and
// in between keeps the state it had in the previous cycle. The hysteresis
// stops a sector whose density hovers near one threshold from flickering,
// which would make the chosen direction jump between cycles.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lvf::vfh
{
class BinaryHistogram
{
   public:
	BinaryHistogram(double tauLow, double tauHigh) : m_tauLow(tauLow), m_tauHigh(tauHigh) {}

	/** The binary histogram of this cycle's densities; remembers it for
	 * the next. Before any cycle (or after reset) every sector is free. */
	const std::vector<uint8_t>& update(const std::vector<double>& density);

	const std::vector<uint8_t>& state() const { return m_blocked; }
	void reset() { m_blocked.clear(); }

   private:
	double m_tauLow, m_tauHigh;
	std::vector<uint8_t> m_blocked;
};

}  // namespace lvf::vfh
