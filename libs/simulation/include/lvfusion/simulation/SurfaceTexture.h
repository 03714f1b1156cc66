#pragma once
// Evaluates a TextureSpec at surface coordinates (u, v) in metres, filtered
// to the size of the camera pixel that sees it.
//
// Noise textures have detail at several scales, from twice the feature size
// down to a quarter of it, like real surfaces. A camera pixel integrates
// everything finer than itself; a renderer that took one point sample per
// pixel would instead alias that detail into noise (at a distance) or show
// only smooth gradients (up close). So the texture is a mip-map: a seeded,
// periodic noise tile and its successive half-resolution averages, sampled
// at the level whose texels match the pixel footprint (trilinear).
// Per-pixel multi-octave hashing would also cost more than the whole ray
// cast; a 1024-texel tile at an eighth of the feature size repeats only every
// 128 features (5 m at the default 4 cm), outside any stereo search range.

#include <lvfusion/simulation/TextureSpec.h>

#include <vector>

namespace cv
{
template <typename T>
class Mat_;
}

namespace lvf::simulation
{
class SurfaceTexture
{
   public:
	SurfaceTexture() = default;
	explicit SurfaceTexture(const TextureSpec& spec);

	/** Reflectance in [0, 1] at surface coordinates (u, v) [m], averaged over
	 * a footprint of `footprint` metres (0: a point sample). */
	float albedoAt(double u, double v, double footprint = 0) const;

   private:
	float sampleLevel(int level, double tu, double tv) const;

	TextureSpec::Kind m_kind = TextureSpec::Kind::None;
	float m_albedo = 0.6f;
	float m_contrast = 0.f;
	double m_texelsPerMetre = 1;
	double m_offsetU = 0, m_offsetV = 0;
	const std::vector<cv::Mat_<float>>* m_pyramid = nullptr;  // values in [-1, 1]
};

}  // namespace lvf::simulation
