#include <lvfusion/common/RowBands.h>
#include <lvfusion/common/VectorClones.h>
#include <lvfusion/depth/CrossTerms.h>

#include <cassert>

#ifdef LVF_HAVE_AVX2_INTRINSICS
#include <immintrin.h>
#endif

namespace lvf::depth
{
namespace
{
/** One row's pair words, cloned for AVX2 (eight at a time). */
LVF_VECTOR_CLONES void pairRow(const uint8_t* in, int width, int32_t* out)
{
	const int last = width - 1;
	for (int x = 0; x < last; x++) out[x] = int32_t{in[x]} | (int32_t{in[x + 1]} << 16);
	out[last] = int32_t{in[last]};
}
}  // namespace

cv::Mat1i neighbourPairs(const cv::Mat1b& image)
{
	cv::Mat1i pairs(image.rows, image.cols);
	lvf::common::forEachRow(
		image.rows, [&](int v) { pairRow(image.ptr<uint8_t>(v), image.cols, pairs.ptr<int32_t>(v)); });
	return pairs;
}

namespace
{
int32_t crossColumn(const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x, int half)
{
	int32_t sum = 0;
	for (int dy = -half; dy <= half; dy++)
	{
		const int32_t* l = leftPairs.ptr<int32_t>(v + dy) + u;
		const int32_t* r = rightPairs.ptr<int32_t>(v + dy) + x;
		for (int dx = -half; dx <= half; dx++) sum += pixelOf(l[dx]) * pixelOf(r[dx]);
	}
	return sum;
}

#ifdef LVF_HAVE_AVX2_INTRINSICS
#define LVF_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

/** acc[k] for the 8 V columns from x on, V registers of eight: for each
 * window row, Half pair words of the left window (columns -Half .. Half - 1
 * two at a time) and its last column alone (the pair word with its
 * neighbour masked off), each broadcast and multiplied-added with the right
 * row's pair words at the matching offset. Half is a template argument so
 * that the window's loops unroll; one register sum per block (integer adds
 * take a cycle, the multiply-adds do not wait for each other). */
template <int V, int Half>
LVF_AVX2_INLINE void pairBlock(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x, int32_t* acc)
{
	__m256i sums[V];
	for (int j = 0; j < V; j++) sums[j] = _mm256_setzero_si256();
	for (int dy = -Half; dy <= Half; dy++)
	{
		const int32_t* l = leftPairs.ptr<int32_t>(v + dy) + u - Half;
		const int32_t* r = rightPairs.ptr<int32_t>(v + dy) + x - Half;
#pragma GCC unroll 8
		for (int p = 0; p <= Half; p++)
		{
			const int32_t word = p < Half ? l[2 * p] : pixelOf(l[2 * p]);
			const __m256i weight = _mm256_set1_epi32(word);
			for (int j = 0; j < V; j++)
			{
				const __m256i column = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(r + 2 * p + 8 * j));
				sums[j] = _mm256_add_epi32(sums[j], _mm256_madd_epi16(weight, column));
			}
		}
	}
	for (int j = 0; j < V; j++) _mm256_storeu_si256(reinterpret_cast<__m256i*>(acc + 8 * j), sums[j]);
}

template <int Half>
LVF_AVX2_INLINE void pairBlocks(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x0, int n, int32_t* acc)
{
	int i = 0;
	for (; i + 32 <= n; i += 32) pairBlock<4, Half>(leftPairs, rightPairs, u, v, x0 + i, acc + i);
	for (; i + 16 <= n; i += 16) pairBlock<2, Half>(leftPairs, rightPairs, u, v, x0 + i, acc + i);
	for (; i + 8 <= n; i += 8) pairBlock<1, Half>(leftPairs, rightPairs, u, v, x0 + i, acc + i);
	for (; i < n; i++) acc[i] = crossColumn(leftPairs, rightPairs, u, v, x0 + i, Half);
}

/** Whether it ran: windows up to 15 x 15 (their sums stay exact in float
 * too, which the scores need). */
__attribute__((target("avx2"))) bool crossTermsAvx2(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x0, int n, int half,
	int32_t* acc)
{
	switch (half)
	{
		case 1: pairBlocks<1>(leftPairs, rightPairs, u, v, x0, n, acc); return true;
		case 2: pairBlocks<2>(leftPairs, rightPairs, u, v, x0, n, acc); return true;
		case 3: pairBlocks<3>(leftPairs, rightPairs, u, v, x0, n, acc); return true;
		case 4: pairBlocks<4>(leftPairs, rightPairs, u, v, x0, n, acc); return true;
		case 5: pairBlocks<5>(leftPairs, rightPairs, u, v, x0, n, acc); return true;
		case 6: pairBlocks<6>(leftPairs, rightPairs, u, v, x0, n, acc); return true;
		case 7: pairBlocks<7>(leftPairs, rightPairs, u, v, x0, n, acc); return true;
		default: return false;
	}
}
#endif
}  // namespace

void crossTermsPlain(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x0, int n, int half,
	int32_t* acc)
{
	for (int i = 0; i < n; i++) acc[i] = crossColumn(leftPairs, rightPairs, u, v, x0 + i, half);
}

void crossTerms(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x0, int n, int half,
	int32_t* acc)
{
	assert(u - half >= 0 && u + half < leftPairs.cols && x0 - half >= 0 && x0 + n - 1 + half < rightPairs.cols);
#ifdef LVF_HAVE_AVX2_INTRINSICS
	if (lvf::common::cpuHasAvx2() && crossTermsAvx2(leftPairs, rightPairs, u, v, x0, n, half, acc)) return;
#endif
	crossTermsPlain(leftPairs, rightPairs, u, v, x0, n, half, acc);
}

}  // namespace lvf::depth
