#pragma once
// Evaluates a TextureSpec at surface coordinates (u, v) in metres.
//
// Noise textures sample one of a few precomputed, seeded noise tiles
// (bilinear, wrapped) at a per-seed offset: per-pixel multi-octave hashing
// would cost more than the whole ray cast, and a 512-texel tile at a quarter
// of the feature size repeats only every 128 features (5 m at the default
// 4 cm), far outside any stereo search range.

#include <lvfusion/simulation/TextureSpec.h>

namespace lvf::simulation
{
class SurfaceTexture
{
   public:
	SurfaceTexture() = default;
	explicit SurfaceTexture(const TextureSpec& spec);

	/** Reflectance in [0, 1] at surface coordinates (u, v) [m]. */
	float albedoAt(double u, double v) const;

   private:
	TextureSpec::Kind m_kind = TextureSpec::Kind::None;
	float m_albedo = 0.6f;
	float m_contrast = 0.f;
	double m_texelsPerMetre = 1;
	double m_offsetU = 0, m_offsetV = 0;
	const float* m_tile = nullptr;	// kTileSize x kTileSize, values in [-1, 1]
};

}  // namespace lvf::simulation
