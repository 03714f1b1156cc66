// World files: elements expand into the right boxes; every mistake is named.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <lvfusion/common/InputError.h>
#include <mrpt/core/bits_math.h>

#include <cmath>

using namespace lvf::simulation;
using lvf::common::InputError;

namespace
{
/** The message of the InputError that parsing `yaml` throws. */
std::string errorOf(const std::string& yaml)
{
	try
	{
		parseWorld(yaml, "bad.yaml");
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return "<no error>";
}
const std::string kPath = "path: {poses: [[0, 0, 0]]}\n";
}  // namespace

TEST(WorldLoader, TableBecomesTopAndFourLegs)
{
	const World w = lvf::test::worldFromText(
		"tables:\n"
		"  - {name: desk, pose: [4, 1, 90], size: [1.4, 0.7], height: 0.75,"
		" top_thickness: 0.04, leg_width: 0.05}\n" + kPath);
	ASSERT_EQ(w.boxes.size(), 5u);
	const Box& top = w.boxes[0];
	EXPECT_EQ(top.name, "desk/top");
	EXPECT_NEAR(top.zMax(), 0.75, 1e-12);
	EXPECT_NEAR(top.zMin(), 0.71, 1e-12);
	for (size_t k = 1; k < 5; k++)
	{
		const Box& leg = w.boxes[k];
		EXPECT_NEAR(leg.zMin(), 0.0, 1e-12);
		EXPECT_NEAR(leg.zMax(), 0.71, 1e-12);
		// Rotated 90 deg: the 1.4 m length runs along y, legs inset by half a leg.
		EXPECT_NEAR(std::abs(leg.x - 4.0), 0.5 * (0.7 - 0.05), 1e-9);
		EXPECT_NEAR(std::abs(leg.y - 1.0), 0.5 * (1.4 - 0.05), 1e-9);
	}
}

TEST(WorldLoader, WallsShelvesAndPaths)
{
	const World w = lvf::test::worldFromText(
		"walls: [{from: [0, 0], to: [3, 4], thickness: 0.2, height: 2}]\n"
		"shelves: [{pose: [1, 1, 0], size: [1.0, 0.3, 0.6], elevation: 1.0, boards: 3}]\n"
		"path: {waypoints: [[0, 0], [1, 0], [1, 1]], step: 0.3}\n"
		"target: [2, 2]\n");
	ASSERT_EQ(w.boxes.size(), 1u + 2u + 3u);
	EXPECT_NEAR(w.boxes[0].sizeX, 5.0, 1e-12);
	EXPECT_NEAR(w.boxes[0].yaw, std::atan2(4, 3), 1e-12);
	EXPECT_NEAR(w.boxes[3].zMin(), 1.0, 1e-12);	 // lowest board
	EXPECT_NEAR(w.boxes.back().zMax(), 1.6, 1e-12);	 // top board
	// 2 m of path every 0.3 m: 0, 0.3, ..., 1.8 and the final waypoint.
	ASSERT_EQ(w.path.size(), 8u);
	EXPECT_NEAR(w.path[4].x, 1.0, 1e-9);
	EXPECT_NEAR(w.path[4].y, 0.2, 1e-9);
	EXPECT_NEAR(w.path[4].phi, M_PI_2, 1e-9);
	EXPECT_NEAR(w.path.back().y, 1.0, 1e-12);
	ASSERT_TRUE(w.target.has_value());
}

TEST(WorldLoader, EveryMistakeIsNamedWithFileLineAndKey)
{
	EXPECT_EQ(
		errorOf("boxes:\n  - {pose: [0, 0, 0], size: [1, -1, 1]}\n" + kPath),
		"bad.yaml: line 2: boxes[0].size[1]: -1 is out of range [1e-06, 1e+300]");
	EXPECT_EQ(
		errorOf("boxes:\n  - {pose: [0, 0, 0], size: [1, 1, 1], colour: red}\n" + kPath),
		"bad.yaml: line 2: boxes[0].colour: unknown key 'colour'");
	EXPECT_EQ(errorOf("boxes:\n  - {pose: [0, 0], size: [1, 1, 1]}\n" + kPath),
		"bad.yaml: line 2: boxes[0].pose: expected a list of 3 numbers");
	EXPECT_EQ(errorOf("name: x\n"), "bad.yaml: line 1: missing key 'path' (the robot's poses)");
	EXPECT_EQ(errorOf("boxes: [\n" + kPath),
		"bad.yaml: line 3: malformed YAML: end of sequence flow not found");
	EXPECT_EQ(errorOf("tables: [{pose: [0,0,0], size: [1,1], height: abc}]\n" + kPath),
		"bad.yaml: line 1: tables[0].height: expected a number");
	EXPECT_EQ(errorOf("floor: {texture: marble}\n" + kPath),
		"bad.yaml: line 1: floor.texture: unknown texture 'marble' (none, noise, checker)");
}

TEST(WorldLoader, MissingFileIsAnInputError)
{
	try
	{
		loadWorldFile("/nonexistent/world.yaml");
		FAIL() << "no error";
	}
	catch (const InputError& e)
	{
		EXPECT_STREQ(e.what(), "/nonexistent/world.yaml: world file not found");
	}
}

TEST(WorldLoader, ShippedWorldsLoad)
{
	for (const char* name : {"box_room", "two_cubes", "corridor_desk"})
	{
		const World w = loadWorldFile(
			std::string(LVF_SHARE_DIR) + "/worlds/" + name + ".yaml");
		EXPECT_EQ(w.name, name);
		EXPECT_FALSE(w.path.empty());
	}
}
