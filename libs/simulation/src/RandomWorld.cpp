#include <lvfusion/simulation/RandomWorld.h>
#include <lvfusion/simulation/WorldLoader.h>

#include <cmath>
#include <random>

namespace lvf::simulation
{
namespace
{
class Dice
{
   public:
	explicit Dice(uint32_t seed) : m_rng(seed) {}
	double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_rng); }
	bool chance(double p) { return uniform(0, 1) < p; }
	uint32_t seed() { return m_rng(); }

   private:
	std::mt19937 m_rng;
};

TextureSpec randomTexture(Dice& dice, double texturelessFraction)
{
	TextureSpec t;
	t.kind = dice.chance(texturelessFraction) ? TextureSpec::Kind::None : TextureSpec::Kind::Noise;
	t.albedo = dice.uniform(0.35, 0.75);
	t.contrast = dice.uniform(0.25, 0.4);
	t.scale = dice.uniform(0.03, 0.07);
	t.seed = dice.seed();
	return t;
}

Box wallBox(double x0, double y0, double x1, double y1, Dice& dice, double textureless)
{
	Box b = wallBetween("wall", {x0, y0}, {x1, y1}, 0.1, 2.5);
	b.texture = randomTexture(dice, textureless);
	return b;
}

}  // namespace

World generateRandomWorld(uint32_t seed, const RandomWorldOptions& o)
{
	Dice dice(seed);
	World w;
	w.name = "random_" + std::to_string(seed);
	const double W = dice.uniform(o.roomMin, o.roomMax), D = dice.uniform(o.roomMin, o.roomMax);
	w.floorTexture = randomTexture(dice, 0.0);
	w.floorTexture.albedo = 0.5;
	// Room [0, W] x [0, D], walls centred 0.05 m outside.
	const double e = 0.05;
	w.boxes.push_back(wallBox(-e, -e, W + e, -e, dice, o.texturelessFraction));
	w.boxes.push_back(wallBox(W + e, -e, W + e, D + e, dice, o.texturelessFraction));
	w.boxes.push_back(wallBox(W + e, D + e, -e, D + e, dice, o.texturelessFraction));
	w.boxes.push_back(wallBox(-e, D + e, -e, -e, dice, o.texturelessFraction));

	const mrpt::math::TPoint2D start(W / 2, 0.6);
	auto placeFree = [&](double radius, double& x, double& y) {
		for (int attempt = 0; attempt < 100; attempt++)
		{
			x = dice.uniform(0.3 + radius, W - 0.3 - radius);
			y = dice.uniform(1.0, D - 0.3 - radius);
			if (std::hypot(x - start.x, y - start.y) > o.clearRadius + radius) return true;
		}
		return false;
	};
	auto addBox = [&](const std::string& name, double sx, double sy, double sz, double elevation) {
		Box b;
		b.name = name;
		b.sizeX = sx;
		b.sizeY = sy;
		b.sizeZ = sz;
		b.elevation = elevation;
		b.yaw = dice.uniform(-M_PI, M_PI);
		b.texture = randomTexture(dice, 0.0);
		if (placeFree(0.5 * std::hypot(sx, sy), b.x, b.y)) w.boxes.push_back(b);
	};
	for (int i = 0; i < o.floorBoxes; i++)
		addBox("floor_box" + std::to_string(i), dice.uniform(0.3, 0.8), dice.uniform(0.3, 0.8), dice.uniform(0.4, 1.0), 0);
	for (int i = 0; i < o.floatingBoxes; i++)
		addBox("floating_box" + std::to_string(i), dice.uniform(0.3, 0.7), dice.uniform(0.3, 0.7),
			   dice.uniform(0.2, 0.4), dice.uniform(0.45, 0.9));
	for (int i = 0; i < o.tables; i++)
	{
		// A top at 0.7..0.8 m on four thin legs.
		const double len = dice.uniform(0.9, 1.5), wid = dice.uniform(0.6, 0.8), h = dice.uniform(0.7, 0.8);
		double x, y;
		if (!placeFree(0.5 * std::hypot(len, wid), x, y)) continue;
		Box top;
		top.name = "table" + std::to_string(i);
		top.x = x, top.y = y, top.yaw = dice.uniform(-M_PI, M_PI), top.sizeX = len, top.sizeY = wid;
		top.texture = randomTexture(dice, 0.0);
		for (const Box& b : tableBoxes(top, h, 0.04, 0.05)) w.boxes.push_back(b);
	}
	for (int i = 0; i < o.wallShelves; i++)
	{
		// On the east or west wall, 0.3 m deep, 0.5 .. 1.0 m above the floor.
		const bool east = dice.chance(0.5);
		Box shelf;
		shelf.name = "shelf" + std::to_string(i);
		shelf.sizeX = 0.3;
		shelf.sizeY = dice.uniform(0.8, 1.4);
		shelf.sizeZ = dice.uniform(0.3, 0.5);
		shelf.elevation = dice.uniform(0.5, 0.8);
		shelf.x = east ? W - 0.15 : 0.15;
		shelf.y = dice.uniform(1.5, D - 1.0);
		shelf.texture = randomTexture(dice, 0.0);
		w.boxes.push_back(shelf);
	}
	for (int k = 0; k < o.pathPoses; k++) w.path.emplace_back(start.x, start.y + 0.2 * k, M_PI_2);
	w.target = mrpt::math::TPoint2D(W - 0.6, D - 0.6);
	return w;
}

}  // namespace lvf::simulation
