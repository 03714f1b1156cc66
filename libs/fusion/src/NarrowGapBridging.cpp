#include <lvfusion/fusion/NarrowGapBridging.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lvf::fusion
{
namespace
{
constexpr float kNone = std::numeric_limits<float>::infinity();

/** Range along the bearing `t` (from a's bearing) to the straight line
 * through the points at ranges ra (bearing 0) and rb (bearing tb). */
double rangeToChord(double ra, double rb, double tb, double t)
{
	return ra * rb * std::sin(tb) / (ra * std::sin(t) + rb * std::sin(tb - t));
}
}  // namespace

std::vector<bool> bridgeNarrowGaps(
	std::vector<float>& visual, const std::vector<float>& laser, double bearingStep, double width,
	double tolerance)
{
	const size_t n = std::min(visual.size(), laser.size());
	// Decided on the ranges as found, so that one bridge never anchors another.
	const std::vector<float> found = visual;
	std::vector<float> fused(n);
	for (size_t i = 0; i < n; i++) fused[i] = std::min(found[i], laser[i]);
	auto byVision = [&](size_t i) { return found[i] <= laser[i]; };
	std::vector<bool> bridged(visual.size(), false);
	for (size_t a = 0; a + 2 < n; a++)
	{
		// Over the bearings between a and b: the nearest fused range, and the
		// nearest range vision placed there itself.
		float nearestBetween = kNone, nearestFoundBetween = kNone;
		for (size_t b = a + 2; b < n; b++)
		{
			nearestBetween = std::min(nearestBetween, fused[b - 1]);
			nearestFoundBetween = std::min(nearestFoundBetween, found[b - 1]);
			const float nearEnd = std::min(fused[a], fused[b]), farEnd = std::max(fused[a], fused[b]);
			if (double(b - a) * bearingStep * nearEnd > width) break;
			if (farEnd - nearEnd > tolerance || !(byVision(a) || byVision(b))) continue;
			// Between the ends: farther than both, and not placed by vision
			// on the same surface already (within the tolerance).
			if (!(nearestBetween > farEnd) || nearestFoundBetween <= farEnd + tolerance) continue;
			const double tb = double(b - a) * bearingStep;
			for (size_t k = a + 1; k < b; k++)
			{
				const auto r = static_cast<float>(rangeToChord(fused[a], fused[b], tb, double(k - a) * bearingStep));
				if (r < visual[k]) visual[k] = r, bridged[k] = true;
			}
			break;
		}
	}
	return bridged;
}

}  // namespace lvf::fusion
