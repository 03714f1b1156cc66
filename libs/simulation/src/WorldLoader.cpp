#include <lvfusion/common/InputError.h>
#include <lvfusion/common/LikelyMeant.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace lvf::simulation
{
using lvf::common::InputError;

namespace
{
// A world is a building: everything within this of its origin [m]. The
// simulator rasterises the whole world at 5 cm for its ground truth
// (obstacleGrid), some 10,000 x 10,000 cells at most; a coordinate mistyped by
// orders of magnitude would otherwise ask for terabytes (a box 100 km out
// failed writing, 10,000 km out crashed: found by tests/fuzz).
constexpr double kMaxCoordinate = 200;
constexpr double kMaxSize = 100;  // largest side of an element [m]

constexpr size_t kMaxPathPoses = 100000;  // a path sampled from waypoints

/** One YAML node plus where it came from, for messages like
 * "world.yaml: line 12: boxes[2].size: ...". */
class Field
{
   public:
	Field(const YAML::Node& node, std::string path, const std::string& source)
		: m_node(node), m_path(std::move(path)), m_source(source)
	{
	}

	[[noreturn]] void fail(const std::string& what) const
	{
		std::string where;
		if (m_node.Mark().line >= 0)
			where = "line " + std::to_string(m_node.Mark().line + 1);
		if (!m_path.empty()) where += (where.empty() ? "" : ": ") + m_path;
		throw InputError(m_source, where, what);
	}

	bool has(const std::string& key) const { return bool(m_node[key]); }
	Field operator[](const std::string& key) const
	{
		const YAML::Node child = m_node[key];
		if (!child) fail("missing key '" + key + "'");
		return Field(child, m_path.empty() ? key : m_path + "." + key, m_source);
	}
	Field item(size_t i) const
	{
		return Field(m_node[i], m_path + "[" + std::to_string(i) + "]", m_source);
	}

	void requireMap(const std::vector<std::string>& allowedKeys) const
	{
		if (!m_node.IsMap()) fail("expected a map of keys");
		for (const auto& kv : m_node)
		{
			const auto key = kv.first.as<std::string>();
			if (std::find(allowedKeys.begin(), allowedKeys.end(), key) ==
				allowedKeys.end())
				Field(kv.first, m_path.empty() ? key : m_path + "." + key, m_source)
					.fail("unknown key '" + key + "'" + lvf::common::didYouMean(key, allowedKeys));
		}
	}
	size_t sequenceSize() const
	{
		if (!m_node.IsSequence()) fail("expected a list");
		return m_node.size();
	}
	bool isScalar() const { return m_node.IsScalar(); }

	std::string text() const
	{
		if (!m_node.IsScalar()) fail("expected a single value");
		return m_node.as<std::string>();
	}
	double number(double minValue = -1e300, double maxValue = 1e300) const
	{
		double v = 0;
		if (!m_node.IsScalar() || !YAML::convert<double>::decode(m_node, v) ||
			!std::isfinite(v))
			fail("expected a number");
		requireWithin(v, minValue, maxValue);
		return v;
	}
	/** `v`, this node's number, must lie in [minValue, maxValue]. */
	void requireWithin(double v, double minValue, double maxValue) const
	{
		if (v < minValue || v > maxValue)
		{
			std::ostringstream s;
			s << v << " is out of range [" << minValue << ", " << maxValue << "]";
			fail(s.str());
		}
	}
	double number(const std::string& key, double defaultValue,
		double minValue = -1e300, double maxValue = 1e300) const
	{
		return has(key) ? (*this)[key].number(minValue, maxValue) : defaultValue;
	}
	std::vector<double> numbers(size_t count, double minValue = -1e300, double maxValue = 1e300) const
	{
		if (!m_node.IsSequence() || m_node.size() != count)
			fail("expected a list of " + std::to_string(count) + " numbers");
		std::vector<double> out;
		for (size_t i = 0; i < count; i++) out.push_back(item(i).number(minValue, maxValue));
		return out;
	}
	/** [x, y] or [x, y, yaw_deg]: x and y within kMaxCoordinate of the
	 * origin, an angle any number of degrees. */
	std::vector<double> position(size_t count) const
	{
		const std::vector<double> out = numbers(count);
		for (size_t i = 0; i < 2 && i < count; i++) item(i).requireWithin(out[i], -kMaxCoordinate, kMaxCoordinate);
		return out;
	}

   private:
	YAML::Node m_node;
	std::string m_path;
	const std::string& m_source;
};

constexpr double kPositive = 1e-6;	// smallest accepted size [m]

class WorldParser
{
   public:
	WorldParser(const std::string& source) : m_source(source) {}

	World parse(const YAML::Node& root)
	{
		Field top(root, "", m_source);
		if (!root.IsMap()) top.fail("a world file must be a map of keys");
		top.requireMap(
			{"name", "seed", "robot", "light", "floor", "walls", "boxes",
			 "tables", "shelves", "path", "target"});
		World w;
		w.sourceFile = m_source;
		w.name = top.has("name") ? top["name"].text() : "world";
		if (!lvf::common::isPlainFileName(w.name)) top["name"].fail(std::string("'") + w.name + "' " + lvf::common::kPlainFileNameRule);
		m_seed = static_cast<uint32_t>(top.number("seed", 1, 0, 4e9));
		if (top.has("robot")) parseRobot(top["robot"], w.robot);
		if (top.has("light")) parseLight(top["light"], w.light);
		w.floorTexture = defaultTexture();
		w.floorTexture.albedo = 0.5;
		if (top.has("floor"))
		{
			const Field f = top["floor"];
			f.requireMap({"texture"});
			if (f.has("texture")) w.floorTexture = parseTexture(f["texture"]);
		}
		forEach(top, "walls", [&](const Field& f) { parseWall(f, w); });
		forEach(top, "boxes", [&](const Field& f) { parseBox(f, w); });
		forEach(top, "tables", [&](const Field& f) { parseTable(f, w); });
		forEach(top, "shelves", [&](const Field& f) { parseShelf(f, w); });
		if (!top.has("path")) top.fail("missing key 'path' (the robot's poses)");
		parsePath(top["path"], w);
		if (top.has("target"))
		{
			const auto t = top["target"].position(2);
			w.target = mrpt::math::TPoint2D(t[0], t[1]);
		}
		return w;
	}

   private:
	template <typename F>
	void forEach(const Field& top, const std::string& key, F&& f)
	{
		if (!top.has(key)) return;
		const Field list = top[key];
		for (size_t i = 0; i < list.sequenceSize(); i++) f(list.item(i));
	}

	/** Elements without a texture get seeded noise, each its own seed. */
	TextureSpec defaultTexture()
	{
		TextureSpec t;
		t.seed = m_seed * 7919u + m_elements++;
		return t;
	}

	TextureSpec parseTexture(const Field& f)
	{
		TextureSpec t = defaultTexture();
		if (f.isScalar())
		{
			if (!parseTextureKind(f.text(), t.kind))
				f.fail("unknown texture '" + f.text() + "' (none, noise, checker)");
			return t;
		}
		f.requireMap({"kind", "albedo", "contrast", "scale", "seed"});
		if (f.has("kind") && !parseTextureKind(f["kind"].text(), t.kind))
			f["kind"].fail(
				"unknown texture kind '" + f["kind"].text() +
				"' (none, noise, checker)");
		t.albedo = f.number("albedo", t.albedo, 0, 1);
		t.contrast = f.number("contrast", t.contrast, 0, 1);
		t.scale = f.number("scale", t.scale, 1e-3, 100);
		t.seed = static_cast<uint32_t>(f.number("seed", t.seed, 0, 4e9));
		return t;
	}

	TextureSpec textureOf(const Field& f)
	{
		return f.has("texture") ? parseTexture(f["texture"]) : defaultTexture();
	}

	std::string nameOf(const Field& f, const std::string& kind, size_t index)
	{
		return f.has("name") ? f["name"].text() : kind + std::to_string(index);
	}

	void parseRobot(const Field& f, RobotBody& r)
	{
		f.requireMap({"radius", "height", "obstacle_min_height"});
		r.radius = f.number("radius", r.radius, kPositive, 10);
		r.height = f.number("height", r.height, kPositive, 10);
		r.obstacleMinHeight =
			f.number("obstacle_min_height", r.obstacleMinHeight, 0, r.height);
	}

	void parseLight(const Field& f, Lighting& l)
	{
		f.requireMap({"direction", "ambient", "diffuse", "background"});
		if (f.has("direction"))
		{
			const auto d = f["direction"].numbers(3);
			const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
			if (n < 1e-9) f["direction"].fail("must not be the zero vector");
			l.dirX = d[0] / n;
			l.dirY = d[1] / n;
			l.dirZ = d[2] / n;
		}
		l.ambient = f.number("ambient", l.ambient, 0, 1);
		l.diffuse = f.number("diffuse", l.diffuse, 0, 1);
		l.background = f.number("background", l.background, 0, 1);
	}

	/** pose: [x, y, yaw_deg] */
	static void readPose(const Field& f, Box& b)
	{
		const auto p = f["pose"].position(3);
		b.x = p[0];
		b.y = p[1];
		b.yaw = mrpt::DEG2RAD(p[2]);
	}

	void parseWall(const Field& f, World& w)
	{
		f.requireMap({"name", "from", "to", "thickness", "height", "elevation", "texture"});
		const auto a = f["from"].position(2), b = f["to"].position(2);
		const std::string name = nameOf(f, "wall", m_walls++);
		if (std::hypot(b[0] - a[0], b[1] - a[1]) < kPositive) f.fail("'from' and 'to' are the same point");
		const double thickness = f.number("thickness", 0.1, kPositive, 10);
		const double height = f.number("height", 2.5, kPositive, 100);
		Box box = wallBetween(name, {a[0], a[1]}, {b[0], b[1]}, thickness, height);
		box.elevation = f.number("elevation", 0, 0, 100);
		box.texture = textureOf(f);
		w.boxes.push_back(box);
	}

	void parseBox(const Field& f, World& w)
	{
		f.requireMap({"name", "pose", "size", "elevation", "texture"});
		Box box;
		box.name = nameOf(f, "box", m_boxCount++);
		readPose(f, box);
		const auto s = f["size"].numbers(3, kPositive, kMaxSize);
		box.sizeX = s[0];
		box.sizeY = s[1];
		box.sizeZ = s[2];
		box.elevation = f.number("elevation", 0, 0, 100);
		box.texture = textureOf(f);
		w.boxes.push_back(box);
	}

	/** A table: a top at `height` and four legs at its corners. */
	void parseTable(const Field& f, World& w)
	{
		f.requireMap({"name", "pose", "size", "height", "top_thickness", "leg_width", "texture"});
		Box top;
		top.name = nameOf(f, "table", m_tables++);
		readPose(f, top);
		const auto s = f["size"].numbers(2, kPositive, kMaxSize);
		const double height = f.number("height", 0.75, kPositive, 10);
		const double thickness = f.number("top_thickness", 0.04, kPositive, height);
		const double leg = f.number(
			"leg_width", 0.05, kPositive, 0.5 * std::min(s[0], s[1]));
		top.sizeX = s[0];
		top.sizeY = s[1];
		top.texture = textureOf(f);
		for (const Box& b : tableBoxes(top, height, thickness, leg)) w.boxes.push_back(b);
	}

	/** A shelf unit: two side panels and evenly spaced boards. With an
	 * elevation it hangs on a wall, out of the laser's plane. */
	void parseShelf(const Field& f, World& w)
	{
		f.requireMap({"name", "pose", "size", "elevation", "boards", "board_thickness", "panel_thickness", "texture"});
		Box frame;
		frame.name = nameOf(f, "shelf", m_shelves++);
		readPose(f, frame);
		const auto s = f["size"].numbers(3, kPositive, kMaxSize);
		frame.elevation = f.number("elevation", 0, 0, 100);
		const int boards = static_cast<int>(f.number("boards", 4, 1, 100));
		const double boardT = f.number("board_thickness", 0.02, kPositive, s[2] / boards);
		const double panelT = f.number("panel_thickness", 0.02, kPositive, 0.25 * s[0]);
		frame.texture = textureOf(f);
		const double c = std::cos(frame.yaw), sn = std::sin(frame.yaw);
		const std::string name = frame.name;
		for (int side = 0; side < 2; side++)
		{
			Box panel = frame;
			panel.name = name + "/panel" + std::to_string(side);
			const double lx = (side ? 0.5 : -0.5) * (s[0] - panelT);
			panel.x = frame.x + c * lx;
			panel.y = frame.y + sn * lx;
			panel.sizeX = panelT;
			panel.sizeY = s[1];
			panel.sizeZ = s[2];
			w.boxes.push_back(panel);
		}
		for (int k = 0; k < boards; k++)
		{
			Box board = frame;
			board.name = name + "/board" + std::to_string(k);
			board.sizeX = s[0] - 2 * panelT;
			board.sizeY = s[1];
			board.sizeZ = boardT;
			board.elevation = frame.elevation +
				(boards == 1 ? 0.0 : (s[2] - boardT) * k / (boards - 1));
			w.boxes.push_back(board);
		}
	}

	void parsePath(const Field& f, World& w)
	{
		f.requireMap({"waypoints", "poses", "step"});
		if (f.has("waypoints") == f.has("poses"))
			f.fail("give exactly one of 'waypoints' or 'poses'");
		if (f.has("poses"))
		{
			const Field list = f["poses"];
			for (size_t i = 0; i < list.sequenceSize(); i++)
			{
				const auto p = list.item(i).position(3);
				w.path.emplace_back(p[0], p[1], mrpt::DEG2RAD(p[2]));
			}
		}
		else
		{
			const double step = f.number("step", 0.25, 1e-3, 100);
			const Field list = f["waypoints"];
			std::vector<mrpt::math::TPoint2D> points;
			for (size_t i = 0; i < list.sequenceSize(); i++)
			{
				const auto p = list.item(i).position(2);
				points.emplace_back(p[0], p[1]);
			}
			if (points.size() < 2) list.fail("needs at least two waypoints");
			double length = 0;
			for (size_t i = 0; i + 1 < points.size(); i++) length += (points[i + 1] - points[i]).norm();
			if (length / step > double(kMaxPathPoses))
				f.fail(mrpt::format("%.0f m of waypoints in steps of %g m are more than %zu poses", length, step, kMaxPathPoses));
			w.path = samplePolyline(points, step);
		}
		if (w.path.empty()) f.fail("the path has no poses");
	}

	const std::string& m_source;
	uint32_t m_seed = 1;
	uint32_t m_elements = 0;
	size_t m_walls = 0, m_boxCount = 0, m_tables = 0, m_shelves = 0;
};

}  // namespace

std::vector<mrpt::math::TPose2D> samplePolyline(
	const std::vector<mrpt::math::TPoint2D>& waypoints, double step)
{
	std::vector<mrpt::math::TPose2D> poses;
	double carried = 0;	 // where the next segment's first sample falls, from its start
	for (size_t i = 0; i + 1 < waypoints.size(); i++)
	{
		const auto& a = waypoints[i];
		const auto& b = waypoints[i + 1];
		const double len = std::hypot(b.x - a.x, b.y - a.y);
		if (len < 1e-9) continue;
		const double yaw = std::atan2(b.y - a.y, b.x - a.x);
		for (double s = carried; s < len - 1e-9; s += step)
			poses.emplace_back(
				a.x + (b.x - a.x) * s / len, a.y + (b.y - a.y) * s / len, yaw);
		carried = std::fmod(carried - len, step);
		if (carried < 0) carried += step;
	}
	if (waypoints.size() >= 2)
	{
		const auto& a = waypoints[waypoints.size() - 2];
		const auto& b = waypoints.back();
		poses.emplace_back(b.x, b.y, std::atan2(b.y - a.y, b.x - a.x));
	}
	return poses;
}

namespace
{
/** "line N" where yaml-cpp knows it. */
std::string yamlPlace(const YAML::Exception& e)
{
	return e.mark.is_null() ? std::string() : "line " + std::to_string(e.mark.line + 1);
}
}  // namespace

World parseWorld(const std::string& yamlText, const std::string& sourceName)
{
	YAML::Node root;
	try
	{
		root = YAML::Load(yamlText);
	}
	catch (const YAML::Exception& e)
	{
		throw InputError(
			sourceName, yamlPlace(e), "malformed YAML: " + e.msg);
	}
	try
	{
		return WorldParser(sourceName).parse(root);
	}
	catch (const YAML::Exception& e)
	{
		// Well-formed YAML whose parts are not what they should be where
		// Field does not check first (a key that is a list or an alias,
		// say): yaml-cpp's conversions throw, with the place.
		throw InputError(
			sourceName, yamlPlace(e), "unexpected value: " + e.msg);
	}
}

World loadWorldFile(const std::string& path)
{
	lvf::common::requireInputFile(path, "world file");
	std::ifstream in(path);
	std::stringstream text;
	text << in.rdbuf();
	return parseWorld(text.str(), path);
}

}  // namespace lvf::simulation
