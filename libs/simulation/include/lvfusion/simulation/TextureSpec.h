#pragma once
// How a surface looks: its mean albedo and, optionally, a seeded procedural
// pattern. "none" gives a uniform, textureless surface (the paper's Fig. 3
// notes that such surfaces cannot be checked by correlation).

#include <cstdint>
#include <string>

namespace lvf::simulation
{
struct TextureSpec
{
	enum class Kind
	{
		None,  //!< uniform albedo
		Noise,	//!< multi-octave value noise (natural, stereo-friendly)
		Checker	 //!< squares of side `scale`, a corner at each face centre
	};
	Kind kind = Kind::Noise;
	double albedo = 0.6;  //!< mean reflectance in [0, 1]
	double contrast = 0.35;	 //!< peak deviation from the mean albedo
	double scale = 0.04;  //!< feature size [m]
	uint32_t seed = 1;

	bool operator==(const TextureSpec& o) const
	{
		return kind == o.kind && albedo == o.albedo && contrast == o.contrast &&
			scale == o.scale && seed == o.seed;
	}
};

/** "none" | "noise" | "checker"; returns false for anything else. */
bool parseTextureKind(const std::string& name, TextureSpec::Kind& out);
std::string textureKindName(TextureSpec::Kind kind);

}  // namespace lvf::simulation
