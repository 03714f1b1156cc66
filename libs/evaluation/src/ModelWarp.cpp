#include <lvfusion/common/RowBands.h>
#include <lvfusion/evaluation/ModelWarp.h>

#include <algorithm>
#include <array>

namespace lvf::evaluation
{
namespace
{
/** cv::remap's fixed point: columns in 1/32 px (INTER_TAB_SIZE). */
constexpr int kSubpixelBits = 5;
constexpr int kSubpixelSteps = 1 << kSubpixelBits;

/** Its linear weights of the right neighbour, k / 32, computed as its
 * table is (the left neighbour's is 1 - that, exact in float). */
std::array<float, kSubpixelSteps> rightWeights()
{
	std::array<float, kSubpixelSteps> w{};
	for (int k = 0; k < kSubpixelSteps; k++) w[size_t(k)] = (1.f / kSubpixelSteps) * float(k);
	return w;
}
}  // namespace

void warpByModel(
	const cv::Mat1b& right, const cv::Mat1f& modelDisparity, const RectifiedGeometry& geometry,
	cv::Mat1f& warped, cv::Mat1b& unverifiable, const cv::Mat1b& rightNotImaged)
{
	static const std::array<float, kSubpixelSteps> kRightWeight = rightWeights();
	const cv::Size size = right.size();
	warped.create(size);
	unverifiable.create(size);
	const int width = size.width;
	const float cxOffset = static_cast<float>(geometry.cxOffset), lastColumn = static_cast<float>(width - 1);
	const bool marked = !rightNotImaged.empty();
	// Rows are independent: on OpenCV's threads (RowBands.h).
	lvf::common::forEachRow(size.height, [&](int v) {
		const float* d = modelDisparity.ptr<float>(v);
		const uint8_t* row = right.ptr<uint8_t>(v);
		float* out = warped.ptr<float>(v);
		uint8_t* bad = unverifiable.ptr<uint8_t>(v);
		const uint8_t* marks = marked ? rightNotImaged.ptr<uint8_t>(v) : nullptr;
		for (int u = 0; u < width; u++)
		{
			const float x = static_cast<float>(u) - d[u] + cxOffset;
			bad[u] = d[u] <= 0 || x < 0 || x > lastColumn ? 255 : 0;
			if (marks && !bad[u])
			{
				const int column = static_cast<int>(x);
				if (marks[column] | marks[std::min(column + 1, width - 1)]) bad[u] = 255;
			}
			// remap rounds the column to the nearest 1/32 (ties to even) and
			// weights its two neighbours; outside the image they are 0.
			const int fixed = cvRound(x * kSubpixelSteps);
			const int left = fixed >> kSubpixelBits;
			const float w1 = kRightWeight[size_t(fixed & (kSubpixelSteps - 1))], w0 = 1.f - w1;
			if (static_cast<unsigned>(left) < static_cast<unsigned>(width - 1))
				out[u] = float(row[left]) * w0 + float(row[left + 1]) * w1;
			else if (left >= width || left + 1 < 0)
				out[u] = 0.f;
			else
				out[u] = (left >= 0 ? float(row[left]) : 0.f) * w0 + (left + 1 < width ? float(row[left + 1]) : 0.f) * w1;
		}
	});
}

}  // namespace lvf::evaluation
