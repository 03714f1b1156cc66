#pragma once
// A simulated indoor world: an infinite floor (z = 0) plus a list of boxes.
// Every element of a world file (walls, boxes, tables, shelves) becomes one or
// more boxes, each a vertical prism with a yaw, an elevation above the floor
// and a texture. That is all the geometry the paper's scenes need, and it keeps
// the ray caster and the ground truth exact and simple.

#include <lvfusion/simulation/TextureSpec.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <optional>
#include <string>
#include <vector>

namespace lvf::simulation
{
struct Box
{
	std::string name;  //!< e.g. "table1/top", used in messages
	double x = 0, y = 0;  //!< centre of the footprint, world frame [m]
	double yaw = 0;  //!< [rad]
	double sizeX = 1, sizeY = 1, sizeZ = 1;	 //!< extents along its own axes [m]
	double elevation = 0;  //!< height of the bottom face above the floor [m]
	TextureSpec texture;

	double zMin() const { return elevation; }
	double zMax() const { return elevation + sizeZ; }
	/** True if some part of the box lies in heights (zLow, zHigh). */
	bool overlapsHeights(double zLow, double zHigh) const
	{
		return zMax() > zLow && zMin() < zHigh;
	}
};

/** The robot whose obstacles we look for (DESIGN.md "robot height band"). */
struct RobotBody
{
	double radius = 0.30;  //!< [m]
	double height = 1.20;  //!< top of the robot above the floor [m]
	double obstacleMinHeight = 0.05;  //!< lower edge of the band [m]
};

struct Lighting
{
	/** Direction *towards* the light, world frame (normalised on load). */
	double dirX = 0.3, dirY = 0.2, dirZ = 0.93;
	double ambient = 0.45;	//!< fraction of albedo lit with no direction
	double diffuse = 0.55;	//!< Lambertian part
	double background = 0.0;  //!< intensity [0,1] of rays that hit nothing
};

/** A wall of `thickness` and `height` whose centre line runs from `from`
 * to `to` (which must differ), untextured. */
Box wallBetween(
	const std::string& name, const mrpt::math::TPoint2D& from, const mrpt::math::TPoint2D& to, double thickness,
	double height);

/** A table: `top` (pose, footprint, texture and name given) made
 * `thickness` thick with its upper face at `height`, and four square legs
 * `legWidth` wide inside its corners, textured as the top; the top first.
 * Names: NAME/top, NAME/leg0..3. */
std::vector<Box> tableBoxes(Box top, double height, double thickness, double legWidth);

struct World
{
	std::string name;
	std::string sourceFile;
	TextureSpec floorTexture;
	std::vector<Box> boxes;
	RobotBody robot;
	Lighting light;
	/** The robot's true poses, one per simulated frame. */
	std::vector<mrpt::math::TPose2D> path;
	/** Navigation target, where the world file gives one. */
	std::optional<mrpt::math::TPoint2D> target;

	/** Axis-aligned bounds of all boxes' footprints, with a margin [m]. */
	void footprintBounds(
		double& xMin, double& xMax, double& yMin, double& yMax,
		double margin = 0.5) const;
};

}  // namespace lvf::simulation
