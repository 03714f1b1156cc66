// lvfusion installed as a user installs it (cmake --install into a prefix of
// the test's own): the installed programs find the installed samples and
// configurations, MRPT's tools load the installed plugin, and a program of
// one's own built with find_package(lvfusion) (the shipped example) fuses the
// sample exactly as lvf-fuse does.

#include "CliTestSupport.h"

#include <algorithm>
#include <cctype>

using namespace lvf::test;

namespace
{
class InstalledPackage : public CliTest
{
   protected:
	void SetUp() override
	{
		CliTest::SetUp();
		m_prefix = m_dir / "prefix";
		const auto r = run(LVF_CMAKE, "--install '" LVF_BUILD_DIR "' --prefix '" + m_prefix.string() + "'");
		ASSERT_EQ(r.status, 0) << r.out << r.err;
	}
	fs::path m_prefix;
};

/** The per-frame column `column` of an lvf-fuse frames CSV. */
std::vector<std::string> columnOf(const fs::path& csv, const std::string& column)
{
	std::vector<std::string> values;
	for (const auto& row : readCsv(csv)) values.push_back(row.at(column));
	return values;
}
}  // namespace

TEST_F(InstalledPackage, TheInstalledProgramsFindTheInstalledSamples)
{
	const fs::path sample = m_prefix / "share/lvfusion/rawlog_samples/box_room.rawlog";
	ASSERT_TRUE(fs::exists(sample));
	for (const char* file : {"config/fusion.ini", "config/navigate.ini", "config/sensors.ini", "worlds/box_room.yaml",
			 "examples/fuse_rawlog/CMakeLists.txt", "rawlog_samples/box_room_truth_scans.csv"})
		EXPECT_TRUE(fs::exists(m_prefix / "share/lvfusion" / file)) << file;
	EXPECT_TRUE(fs::exists(m_prefix / "include/lvfusion/fusion/CLaserStereoFusion.h"));
	EXPECT_FALSE(fs::exists(m_prefix / "bin/lvf-bench"));  // a developer's tool

	// With no arguments the installed lvf-fuse fuses the installed sample,
	// scored against the truth installed beside it, as the build's does.
	const auto installed = run((m_prefix / "bin/lvf-fuse").string(), "--outdir installed");
	ASSERT_EQ(installed.status, 0) << installed.err;
	EXPECT_NE(installed.out.find(sample.string() + ":"), std::string::npos) << installed.out;
	const auto built = run(LVF_FUSE_BIN, "--outdir built");
	ASSERT_EQ(built.status, 0) << built.err;
	const std::regex score(R"(recall [0-9.]+ of \d+ hidden bearings, phantom rate [0-9.]+ of \d+ in view)");
	std::smatch a, b;
	ASSERT_TRUE(std::regex_search(installed.out, a, score)) << installed.out;
	ASSERT_TRUE(std::regex_search(built.out, b, score)) << built.out;
	EXPECT_EQ(a.str(), b.str());

	// The others read their installed defaults: the world and navigation INI.
	const auto help = run((m_prefix / "bin/lvf-navigate").string(), "--help");
	std::string unwrapped = help.out;  // (TCLAP wraps the help text)
	unwrapped.erase(std::remove_if(unwrapped.begin(), unwrapped.end(), ::isspace), unwrapped.end());
	EXPECT_NE(unwrapped.find((m_prefix / "share/lvfusion/config/navigate.ini").string()), std::string::npos) << help.out;
	const auto simulated = run((m_prefix / "bin/lvf-simulate").string(), "--frames 1 -q --outdir sim");
	ASSERT_EQ(simulated.status, 0) << simulated.err;
	EXPECT_TRUE(fs::exists(m_dir / "sim/box_room.rawlog"));

	// MRPT's own tool loads the installed plugin (it says so only on failure).
#if defined(__SANITIZE_ADDRESS__)
	// (A sanitized plugin loads only into a sanitized process: MRPT's
	// rawlog-edit is not one. test_plugin loads it into its own.)
#else
	const auto info = run(LVF_RAWLOG_EDIT, "--plugins '" + (m_prefix / "lib/liblvfusion.so").string() + "' --info -i '" +
		sample.string() + "'");
	ASSERT_EQ(info.status, 0) << info.err;
	EXPECT_EQ((info.out + info.err).find("Error loading"), std::string::npos) << info.out << info.err;
#endif
}

TEST_F(InstalledPackage, AProgramBuiltWithFindPackageFusesAsLvfFuseDoes)
{
	const fs::path example = m_prefix / "share/lvfusion/examples/fuse_rawlog";
	const auto configured = run(LVF_CMAKE, "-S '" + example.string() + "' -B example -DCMAKE_PREFIX_PATH='" +
		m_prefix.string() + "' -DCMAKE_BUILD_TYPE=Release" + LVF_EXAMPLE_SANITIZER_FLAGS);
	ASSERT_EQ(configured.status, 0) << configured.out << configured.err;
	const auto built = run(LVF_CMAKE, "--build example");
	ASSERT_EQ(built.status, 0) << built.out << built.err;

	const fs::path sample = m_prefix / "share/lvfusion/rawlog_samples/box_room.rawlog";
	const auto fused = run((m_dir / "example/fuse_rawlog").string(), "'" + sample.string() + "'");
	ASSERT_EQ(fused.status, 0) << fused.err;
	std::vector<std::string> shortened;
	const std::regex line(R"(frame \d+: (\d+) of 181 bearings nearer than the laser)");
	for (std::sregex_iterator it(fused.out.begin(), fused.out.end(), line), end; it != end; ++it)
		shortened.push_back((*it)[1]);

	const auto reference = run(LVF_FUSE_BIN, "--input '" + sample.string() + "' --outdir reference");
	ASSERT_EQ(reference.status, 0) << reference.err;
	const auto expected = columnOf(m_dir / "reference/box_room_frames.csv", "shortened_bearings");
	EXPECT_EQ(shortened, expected) << fused.out;
	EXPECT_EQ(expected.size(), 8u);

	const auto missing = run((m_dir / "example/fuse_rawlog").string(), "no_such.rawlog");
	EXPECT_EQ(missing.status, 2);
	EXPECT_EQ(missing.err, "fuse_rawlog: no_such.rawlog: no such rawlog\n");
}

// The Debian package (cpack, README): the same install under /usr, its
// runtime dependencies read from the programs, and its lvf-fuse, unpacked
// anywhere, fuses its own sample.
TEST_F(CliTest, TheDebianPackageHoldsTheInstallAndNamesItsLibraries)
{
	const auto packed = run(LVF_CPACK, "--config '" LVF_BUILD_DIR "/CPackConfig.cmake' -B '" + (m_dir / "deb").string() + "'");
	ASSERT_EQ(packed.status, 0) << packed.out << packed.err;
	fs::path deb;
	for (const auto& entry : fs::directory_iterator(m_dir / "deb"))
		if (entry.path().extension() == ".deb") deb = entry.path();
	ASSERT_FALSE(deb.empty()) << packed.out;

	const auto depends = run("dpkg-deb", "-f '" + deb.string() + "' Depends");
	ASSERT_EQ(depends.status, 0) << depends.err;
	for (const char* library : {"libmrpt-maps", "libmrpt-nav", "libopencv-core", "libyaml-cpp"})
		EXPECT_NE(depends.out.find(library), std::string::npos) << library << " in: " << depends.out;

	const fs::path root = m_dir / "root";
	ASSERT_EQ(run("dpkg-deb", "-x '" + deb.string() + "' '" + root.string() + "'").status, 0);
	for (const char* file : {"usr/bin/lvf-fuse", "usr/bin/lvf-navigate", "usr/lib/liblvfusion.so",
			 "usr/share/lvfusion/config/fusion.ini", "usr/share/lvfusion/rawlog_samples/box_room.rawlog",
			 "usr/lib/cmake/lvfusion/lvfusionConfig.cmake", "usr/include/lvfusion/vfh/CHolonomicVFH.h"})
		EXPECT_TRUE(fs::exists(root / file)) << file;
	const auto fused = run((root / "usr/bin/lvf-fuse").string(), "-q --outdir unpacked");
	ASSERT_EQ(fused.status, 0) << fused.err;
	EXPECT_TRUE(fs::exists(m_dir / "unpacked/box_room_fused.rawlog"));
}
