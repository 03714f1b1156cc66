#include <lvfusion/common/LikelyMeant.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>

namespace lvf::common
{
namespace
{
/** Edits between a and b, a swap of neighbours counting as one (the
 * "optimal string alignment" distance). Written here because none of the
 * project's libraries (MRPT, OpenCV, Eigen) offers one. */
size_t editDistance(const std::string& a, const std::string& b)
{
	const size_t n = a.size(), m = b.size();
	// d[i][j]: edits between a's first i characters and b's first j.
	std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
	for (size_t i = 0; i <= n; i++) d[i][0] = i;
	for (size_t j = 0; j <= m; j++) d[0][j] = j;
	for (size_t i = 1; i <= n; i++)
		for (size_t j = 1; j <= m; j++)
		{
			const size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
			d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
				d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
		}
	return d[n][m];
}
}  // namespace

std::string likelyMeant(const std::string& name, const std::vector<std::string>& known)
{
	const std::string typed = mrpt::system::lowerCase(name);
	if (typed.empty()) return "";
	const size_t most = std::min<size_t>(2, (typed.size() - 1) / 3);
	std::string best, bestLowered;
	size_t bestDistance = most + 1;
	bool tie = false;
	for (const auto& candidate : known)
	{
		const std::string lowered = mrpt::system::lowerCase(candidate);
		const size_t distance = editDistance(typed, lowered);
		if (distance < bestDistance) best = candidate, bestLowered = lowered, bestDistance = distance, tie = false;
		else if (distance == bestDistance && lowered != bestLowered) tie = true;
	}
	return bestDistance <= most && !tie ? best : "";
}

std::string didYouMean(const std::string& name, const std::vector<std::string>& known)
{
	const std::string meant = likelyMeant(name, known);
	return meant.empty() ? "" : " (did you mean '" + meant + "'?)";
}

}  // namespace lvf::common
