#include <lvfusion/simulation/SurfaceTexture.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace lvf::simulation
{
namespace
{
constexpr int kTileSize = 1024;	 // power of two: coordinates wrap by masking
constexpr int kTexelsPerFeature = 8;
constexpr int kTileCount = 4;

/** Octaves from twice the feature size down to a quarter of it, normalised
 * so that +-2.5 sigma spans [-1, 1]. */
cv::Mat1f makeNoiseTile(uint64_t seed)
{
	cv::RNG rng(seed);
	cv::Mat1f tile = cv::Mat1f::zeros(kTileSize, kTileSize);
	const std::array<std::pair<int, float>, 4> octaves{
		{{kTexelsPerFeature * 2, 0.5f},	 // coarse blotches
		 {kTexelsPerFeature, 1.0f},	 // the nominal feature size
		 {kTexelsPerFeature / 2, 0.6f},
		 {kTexelsPerFeature / 4, 0.4f}}};  // fine grain
	for (const auto& [texelsPerValue, weight] : octaves)
	{
		const int n = kTileSize / texelsPerValue;
		cv::Mat1f coarse(n, n);
		rng.fill(coarse, cv::RNG::UNIFORM, -1.0, 1.0);
		// Pad periodically before interpolating so the tile wraps without a
		// seam (a straight seam would be a false stereo feature).
		constexpr int pad = 2;
		cv::Mat1f padded, fine;
		cv::copyMakeBorder(coarse, padded, pad, pad, pad, pad, cv::BORDER_WRAP);
		cv::resize(padded, fine, cv::Size(), texelsPerValue, texelsPerValue, cv::INTER_CUBIC);
		const int crop = pad * texelsPerValue;
		tile += weight * fine(cv::Rect(crop, crop, kTileSize, kTileSize));
	}
	cv::Scalar mean, stddev;
	cv::meanStdDev(tile, mean, stddev);
	tile = (tile - mean[0]) / (2.5 * stddev[0]);
	cv::min(cv::max(tile, -1.0), 1.0, tile);
	return tile;
}

/** The tile and its 2x2 averages down to 1 texel (exact box filtering, so
 * the pyramid stays periodic). */
std::vector<cv::Mat1f> makePyramid(const cv::Mat1f& tile)
{
	std::vector<cv::Mat1f> levels{tile};
	while (levels.back().cols > 1)
	{
		cv::Mat1f half;
		cv::resize(levels.back(), half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
		levels.push_back(half);
	}
	return levels;
}

const std::vector<cv::Mat1f>& noisePyramid(uint32_t seed)
{
	static const std::array<std::vector<cv::Mat1f>, kTileCount> pyramids = [] {
		std::array<std::vector<cv::Mat1f>, kTileCount> p;
		for (int i = 0; i < kTileCount; i++) p[i] = makePyramid(makeNoiseTile(0x5eed + i));
		return p;
	}();
	return pyramids[seed % kTileCount];
}

/** A reproducible pseudo-random number in [0, 1) from a seed (splitmix64). */
double unitHash(uint64_t x)
{
	x += 0x9e3779b97f4a7c15ULL;
	x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
	x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
	x ^= x >> 31;
	return static_cast<double>(x >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace

SurfaceTexture::SurfaceTexture(const TextureSpec& spec)
	: m_kind(spec.kind),
	  m_albedo(static_cast<float>(spec.albedo)),
	  m_contrast(static_cast<float>(spec.contrast))
{
	if (m_kind == TextureSpec::Kind::None) return;
	if (m_kind == TextureSpec::Kind::Checker)
	{
		m_texelsPerMetre = 1.0 / spec.scale;
		return;
	}
	m_texelsPerMetre = kTexelsPerFeature / spec.scale;
	m_pyramid = &noisePyramid(spec.seed);
	m_offsetU = kTileSize * unitHash(2 * uint64_t(spec.seed));
	m_offsetV = kTileSize * unitHash(2 * uint64_t(spec.seed) + 1);
}

float SurfaceTexture::sampleLevel(int level, double tu, double tv) const
{
	const cv::Mat1f& tile = (*m_pyramid)[static_cast<size_t>(level)];
	const double scale = 1.0 / double(1 << level);
	tu = tu * scale - 0.5;	// texel centres at half-integers of the level
	tv = tv * scale - 0.5;
	const double fu = std::floor(tu), fv = std::floor(tv);
	const float au = static_cast<float>(tu - fu), av = static_cast<float>(tv - fv);
	const long mask = tile.cols - 1;
	const long iu = static_cast<long>(fu) & mask, iv = static_cast<long>(fv) & mask;
	const long iu1 = (iu + 1) & mask, iv1 = (iv + 1) & mask;
	const float* r0 = tile.ptr<float>(static_cast<int>(iv));
	const float* r1 = tile.ptr<float>(static_cast<int>(iv1));
	const float top = r0[iu] + au * (r0[iu1] - r0[iu]);
	const float bottom = r1[iu] + au * (r1[iu1] - r1[iu]);
	return top + av * (bottom - top);
}

float SurfaceTexture::albedoAt(double u, double v, double footprint) const
{
	switch (m_kind)
	{
		case TextureSpec::Kind::None:
			return m_albedo;
		case TextureSpec::Kind::Checker:
		{
			const auto cu = static_cast<long>(std::floor(u * m_texelsPerMetre));
			const auto cv = static_cast<long>(std::floor(v * m_texelsPerMetre));
			return m_albedo + (((cu + cv) & 1) ? m_contrast : -m_contrast);
		}
		case TextureSpec::Kind::Noise:
		default:
		{
			const double tu = u * m_texelsPerMetre + m_offsetU;
			const double tv = v * m_texelsPerMetre + m_offsetV;
			// Level whose texel is as large as the pixel footprint: log2 of
			// the footprint in texels, from the float's exponent and a linear
			// mantissa (exact at powers of two, within 0.09 between: enough
			// to choose and blend levels, and far cheaper than std::log2).
			const double texels = std::max(1.0, footprint * m_texelsPerMetre);
			int exponent;
			const double mantissa = std::frexp(texels, &exponent);  // [0.5, 1)
			const double lod = (exponent - 1) + (2 * mantissa - 1);
			const int top = static_cast<int>(m_pyramid->size()) - 1;
			const int l0 = std::min(static_cast<int>(lod), top);
			const float w = l0 < top ? static_cast<float>(lod - l0) : 0.f;
			float value = sampleLevel(l0, tu, tv);
			// Blend towards the next level only where it is worth a lookup.
			if (w > 0.05f) value += w * (sampleLevel(l0 + 1, tu, tv) - value);
			return m_albedo + m_contrast * value;
		}
	}
}

bool parseTextureKind(const std::string& name, TextureSpec::Kind& out)
{
	if (name == "none") out = TextureSpec::Kind::None;
	else if (name == "noise") out = TextureSpec::Kind::Noise;
	else if (name == "checker") out = TextureSpec::Kind::Checker;
	else return false;
	return true;
}

std::string textureKindName(TextureSpec::Kind kind)
{
	switch (kind)
	{
		case TextureSpec::Kind::None: return "none";
		case TextureSpec::Kind::Checker: return "checker";
		default: return "noise";
	}
}

}  // namespace lvf::simulation
