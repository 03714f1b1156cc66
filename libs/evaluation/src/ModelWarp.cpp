#include <lvfusion/common/RowBands.h>
#include <lvfusion/common/VectorClones.h>
#include <lvfusion/evaluation/ModelWarp.h>

#include <algorithm>
#include <array>
#include <cstring>

#ifdef LVF_HAVE_AVX2_INTRINSICS
#include <immintrin.h>
#endif

namespace lvf::evaluation
{
namespace
{
/** cv::remap's fixed point: columns in 1/32 px (INTER_TAB_SIZE). */
constexpr int kSubpixelBits = 5;
constexpr int kSubpixelSteps = 1 << kSubpixelBits;

/** One row of the warp: the right image's row `row` sampled where the
 * model sends each left column. */
struct WarpRow
{
	const float* disparity;
	const uint8_t* row;
	uint16_t* out;
	uint8_t* bad;
	int width;
	float cxOffset;

	float columnAt(int u) const { return static_cast<float>(u) - disparity[u] + cxOffset; }

	/** Columns [u0, u1), one at a time. */
	void plain(int u0, int u1) const
	{
		const float lastColumn = static_cast<float>(width - 1);
		for (int u = u0; u < u1; u++)
		{
			const float x = columnAt(u);
			bad[u] = disparity[u] <= 0 || x < 0 || x > lastColumn ? 255 : 0;
			// remap rounds the column to the nearest 1/32 (ties to even) and
			// weights its two neighbours k / 32 and 1 - k / 32; outside the
			// image they are 0.
			const int fixed = cvRound(x * kSubpixelSteps);
			const int left = fixed >> kSubpixelBits, k = fixed & (kSubpixelSteps - 1);
			const int p0 = left >= 0 && left < width ? row[left] : 0;
			const int p1 = left + 1 >= 0 && left + 1 < width ? row[left + 1] : 0;
			out[u] = static_cast<uint16_t>(p0 * (kSubpixelSteps - k) + p1 * k);
		}
	}

	/** Also unverifiable: pixels whose column lies next to one that
	 * rectification filled from outside the camera's image. */
	void markFilled(const uint8_t* marks) const
	{
		for (int u = 0; u < width; u++)
		{
			if (bad[u]) continue;
			const int column = static_cast<int>(columnAt(u));
			if (marks[column] | marks[std::min(column + 1, width - 1)]) bad[u] = 255;
		}
	}

#ifdef LVF_HAVE_AVX2_INTRINSICS
	/** The same, eight columns at a time: the two neighbours of each
	 * fetched by one gather (which the compiler does not emit for bytes;
	 * the plain row took 0.65 ms of a 640x480 frame, this 0.23 in a
	 * throw-away timing loop). The same column as plain()'s, so the same
	 * values: no fused multiply-add (AVX2 has none), the rounding
	 * conversion in the default round-to-nearest-even as cvRound's, the
	 * weighting in integers.
	 * Blocks with a column whose 4-byte gather would leave [0, width)
	 * go the plain way. */
	__attribute__((target("avx2"))) void avx2() const
	{
		// The unverifiable flags of eight columns from the sign mask.
		static const auto kFlagBytes = [] {
			std::array<uint64_t, 256> t{};
			for (int m = 0; m < 256; m++)
				for (int j = 0; j < 8; j++)
					if (m >> j & 1) t[size_t(m)] |= uint64_t(255) << (8 * j);
			return t;
		}();
		const __m256 lanes = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7), zero = _mm256_setzero_ps();
		const __m256 lastColumn = _mm256_set1_ps(static_cast<float>(width - 1));
		const __m256i lowByte = _mm256_set1_epi32(0xff), lastGather = _mm256_set1_epi32(width - 4);
		const __m256i steps = _mm256_set1_epi32(kSubpixelSteps), fraction = _mm256_set1_epi32(kSubpixelSteps - 1);
		int u = 0;
		for (; u + 8 <= width; u += 8)
		{
			const __m256 d = _mm256_loadu_ps(disparity + u);
			const __m256 x = _mm256_add_ps(
				_mm256_sub_ps(_mm256_add_ps(_mm256_set1_ps(static_cast<float>(u)), lanes), d), _mm256_set1_ps(cxOffset));
			const __m256 outside = _mm256_or_ps(
				_mm256_or_ps(_mm256_cmp_ps(d, zero, _CMP_LE_OQ), _mm256_cmp_ps(x, zero, _CMP_LT_OQ)),
				_mm256_cmp_ps(x, lastColumn, _CMP_GT_OQ));
			const __m256i fixed = _mm256_cvtps_epi32(_mm256_mul_ps(x, _mm256_set1_ps(kSubpixelSteps)));
			const __m256i left = _mm256_srai_epi32(fixed, kSubpixelBits);
			const __m256i beyond = _mm256_or_si256(
				_mm256_cmpgt_epi32(_mm256_setzero_si256(), left), _mm256_cmpgt_epi32(left, lastGather));
			if (!_mm256_testz_si256(beyond, beyond))
			{
				plain(u, u + 8);
				continue;
			}
			const uint64_t flags = kFlagBytes[size_t(_mm256_movemask_ps(outside))];
			std::memcpy(bad + u, &flags, sizeof flags);
			const __m256i pairs = _mm256_i32gather_epi32(reinterpret_cast<const int*>(row), left, 1);
			// p0 (32 - k) + p1 k as one 16-bit multiply-add of the words
			// (p0, p1) and (32 - k, k).
			const __m256i p0 = _mm256_and_si256(pairs, lowByte);
			const __m256i p1 = _mm256_and_si256(_mm256_srli_epi32(pairs, 8), lowByte);
			const __m256i k = _mm256_and_si256(fixed, fraction);
			const __m256i sums = _mm256_madd_epi16(_mm256_or_si256(p0, _mm256_slli_epi32(p1, 16)),
				_mm256_or_si256(_mm256_sub_epi32(steps, k), _mm256_slli_epi32(k, 16)));
			// Eight 32-bit sums to 16 bits: packed within each half, the
			// halves' low quarters then brought together.
			const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(sums, sums), 0b1000);
			_mm_storeu_si128(reinterpret_cast<__m128i*>(out + u), _mm256_castsi256_si128(packed));
		}
		plain(u, width);
	}
#endif
};
}  // namespace

void warpByModel(
	const cv::Mat1b& right, const cv::Mat1f& modelDisparity, const RectifiedGeometry& geometry,
	cv::Mat1w& warped32, cv::Mat1b& unverifiable, const cv::Mat1b& rightNotImaged)
{
	const cv::Size size = right.size();
	warped32.create(size);
	unverifiable.create(size);
	// Rows are independent: on OpenCV's threads (RowBands.h).
	lvf::common::forEachRow(size.height, [&](int v) {
		const WarpRow row{modelDisparity.ptr<float>(v), right.ptr<uint8_t>(v), warped32.ptr<uint16_t>(v),
			unverifiable.ptr<uint8_t>(v), size.width, static_cast<float>(geometry.cxOffset)};
#ifdef LVF_HAVE_AVX2_INTRINSICS
		if (lvf::common::cpuHasAvx2())
			row.avx2();
		else
#endif
			row.plain(0, size.width);
		if (!rightNotImaged.empty()) row.markFilled(rightNotImaged.ptr<uint8_t>(v));
	});
}

}  // namespace lvf::evaluation
