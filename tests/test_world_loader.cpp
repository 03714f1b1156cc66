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
		"bad.yaml: line 2: boxes[0].size[1]: -1 is out of range [1e-06, 100]");
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

// Found by tests/fuzz/fuzz_world_file: well-formed YAML whose key is no
// single value (here a list, or an anchor on a key) escaped as yaml-cpp's
// own exception, which the apps report as an internal error (status 1).
TEST(WorldLoader, AKeyThatIsNoSingleValueIsNamedWithItsLine)
{
	EXPECT_EQ(errorOf("boxes: []\n[a, b]: 1\n" + kPath), "bad.yaml: line 2: unexpected value: bad conversion");
	EXPECT_EQ(errorOf("walls:\n  - {name: w, &rom: [-1, 1.2], to: [10, 1.2]}\n" + kPath),
		"bad.yaml: line 2: unexpected value: bad conversion");
}

// Found by tests/fuzz/fuzz_world_file: a coordinate mistyped by orders of
// magnitude (a box 100 km out made lvf-simulate fail writing its ground-truth
// grid, 10,000 km out crash; a waypoint 1e46 m out sampled poses until memory
// ran out). A world is a building: 200 m of its origin, sides up to 100 m,
// paths up to 100,000 poses.
TEST(WorldLoader, AWorldBeyondABuildingsSizeIsRefusedBeforeAnythingIsBuilt)
{
	EXPECT_EQ(errorOf("boxes:\n  - {pose: [100000, 0, 0], size: [1, 1, 1]}\n" + kPath),
		"bad.yaml: line 2: boxes[0].pose[0]: 100000 is out of range [-200, 200]");
	EXPECT_EQ(errorOf("boxes:\n  - {pose: [0, 0, 0], size: [1, 1e9, 1]}\n" + kPath),
		"bad.yaml: line 2: boxes[0].size[1]: 1e+09 is out of range [1e-06, 100]");
	EXPECT_EQ(errorOf("path:\n  waypoints: [[0, 0], [1e46, 0.8]]\n"),
		"bad.yaml: line 2: path.waypoints[1][0]: 1e+46 is out of range [-200, 200]");
	EXPECT_EQ(errorOf("path:\n  waypoints: [[0, 0], [150, 0], [0, 0]]\n  step: 0.001\n"),
		"bad.yaml: line 2: path: 300 m of waypoints in steps of 0.001 m are more than 100000 poses");
	EXPECT_EQ(errorOf("walls:\n  - {from: [0, -250], to: [0, 5]}\n" + kPath),
		"bad.yaml: line 2: walls[0].from[1]: -250 is out of range [-200, 200]");
	EXPECT_EQ(errorOf("path: {poses: [[0, 0, 0]]}\ntarget: [0, 201]\n"),
		"bad.yaml: line 2: target[1]: 201 is out of range [-200, 200]");
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
