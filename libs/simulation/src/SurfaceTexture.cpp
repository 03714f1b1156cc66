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
constexpr int kTileSize = 512;
constexpr int kTexelsPerFeature = 4;
constexpr int kTileCount = 4;

/** Sum of three octaves of smooth random noise, normalised to [-1, 1]. */
cv::Mat1f makeNoiseTile(uint64_t seed)
{
	cv::RNG rng(seed);
	cv::Mat1f tile = cv::Mat1f::zeros(kTileSize, kTileSize);
	const std::array<std::pair<int, float>, 3> octaves{
		{{kTexelsPerFeature * 2, 0.5f},	 // coarse blotches
		 {kTexelsPerFeature, 1.0f},	 // the nominal feature size
		 {kTexelsPerFeature / 2, 0.5f}}};  // fine grain
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
		cv::resize(
			padded, fine, cv::Size(), texelsPerValue, texelsPerValue,
			cv::INTER_CUBIC);
		const int crop = pad * texelsPerValue;
		tile += weight * fine(cv::Rect(crop, crop, kTileSize, kTileSize));
	}
	cv::Scalar mean, stddev;
	cv::meanStdDev(tile, mean, stddev);
	// Scale so that +-2.5 sigma spans [-1, 1], then clip the rare tails.
	tile = (tile - mean[0]) / (2.5 * stddev[0]);
	cv::min(cv::max(tile, -1.0), 1.0, tile);
	return tile;
}

const cv::Mat1f& noiseTile(uint32_t seed)
{
	static const std::array<cv::Mat1f, kTileCount> tiles = [] {
		std::array<cv::Mat1f, kTileCount> t;
		for (int i = 0; i < kTileCount; i++) t[i] = makeNoiseTile(0x5eed + i);
		return t;
	}();
	return tiles[seed % kTileCount];
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
	m_tile = noiseTile(spec.seed).ptr<float>();
	m_offsetU = kTileSize * unitHash(2 * uint64_t(spec.seed));
	m_offsetV = kTileSize * unitHash(2 * uint64_t(spec.seed) + 1);
}

float SurfaceTexture::albedoAt(double u, double v) const
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
			const double fu = std::floor(tu), fv = std::floor(tv);
			const float au = static_cast<float>(tu - fu);
			const float av = static_cast<float>(tv - fv);
			constexpr long mask = kTileSize - 1;  // power of two: wrap by mask
			const long iu = static_cast<long>(fu) & mask;
			const long iv = static_cast<long>(fv) & mask;
			const long iu1 = (iu + 1) & mask, iv1 = (iv + 1) & mask;
			const float* r0 = m_tile + iv * kTileSize;
			const float* r1 = m_tile + iv1 * kTileSize;
			const float top = r0[iu] + au * (r0[iu1] - r0[iu]);
			const float bottom = r1[iu] + au * (r1[iu1] - r1[iu]);
			return m_albedo + m_contrast * (top + av * (bottom - top));
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
