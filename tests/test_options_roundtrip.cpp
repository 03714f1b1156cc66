// Every configuration written by saveToConfigFile (what --dump-config prints)
// loads back to the same options, in memory and through text, and a key
// nobody reads is refused.

#include <gtest/gtest.h>
#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cstdio>
#include <fstream>

namespace
{
template <typename Options>
std::string dump(const Options& o, const std::string& section)
{
	mrpt::config::CConfigFileMemory cfg;
	o.saveToConfigFile(cfg, section);
	return cfg.getContent();
}

template <typename Options>
void expectRoundTrip(Options changed, const std::string& section)
{
	mrpt::config::CConfigFileMemory written;
	changed.saveToConfigFile(written, section);
	Options inMemory, throughText;
	inMemory.loadFromConfigFile(written, section);
	throughText.loadFromConfigFile(mrpt::config::CConfigFileMemory(written.getContent()), section);
	EXPECT_EQ(dump(inMemory, section), dump(changed, section));
	EXPECT_EQ(dump(throughText, section), dump(changed, section));
	EXPECT_NE(dump(changed, section), dump(Options(), section)) << "the test must change something";
}
/** openIniFile refuses a file holding `text` with the line PATH: `message`. */
void expectIniRefused(const std::string& name, const std::string& text, const std::string& message)
{
	const std::string path = ::testing::TempDir() + name;
	std::ofstream(path) << text;
	try
	{
		lvf::common::openIniFile(path);
		ADD_FAILURE() << name << ": no error";
	}
	catch (const lvf::common::InputError& e)
	{
		EXPECT_EQ(std::string(e.what()), path + ": " + message);
	}
	std::remove(path.c_str());
}
}  // namespace

TEST(Options, SimulatorRoundTrips)
{
	lvf::simulation::CStereoLaserSimulator::TOptions o;
	o.seed = 17;
	o.stereo.dist = {-0.1, 0.01, 0, 0, 0.001};
	o.stereo.tiltDeg = 7.5;
	o.laser.noiseStd = 0.02;
	o.odometry.yawStdPerMetre = 0.002;
	expectRoundTrip(o, "CStereoLaserSimulator");
}

TEST(Options, FusionRoundTrips)
{
	lvf::fusion::CLaserStereoFusion::TOptions o;
	o.band.high = 1.5;
	o.lines.splitDistance = 0.2;
	o.evaluation.windowSize = 9;
	o.depth.criterionB = false;
	o.depth.zMax = 4.0;
	o.fusion.minPoints = 4;
	expectRoundTrip(o, "CLaserStereoFusion");
}

namespace
{
/** The error loading `ini` into the fusion's options gives ("" if none). */
std::string fusionOptionsError(const std::string& ini)
{
	mrpt::config::CConfigFileMemory cfg(ini);
	lvf::fusion::CLaserStereoFusion::TOptions o;
	try
	{
		o.loadFromConfigFile(cfg, "CLaserStereoFusion");
	}
	catch (const lvf::common::InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(Options, UnknownKeyIsRefusedWithItsNameAndTheKeyLikelyMeant)
{
	EXPECT_EQ(fusionOptionsError("[CLaserStereoFusion]\nrobot_hieght = 1.0\n"),
		"<memory>: [CLaserStereoFusion] robot_hieght: unknown key (did you mean 'robot_height'?)");
	EXPECT_EQ(fusionOptionsError("[FocusedEpipolarSearch]\nz_mx = 4\n"),
		"<memory>: [FocusedEpipolarSearch] z_mx: unknown key (did you mean 'z_max'?)");
	// Nothing near: no guess.
	EXPECT_EQ(fusionOptionsError("[ScanFusion]\ncolour = 1\n"), "<memory>: [ScanFusion] colour: unknown key");
}

TEST(Options, AKeyInTheWrongSectionIsRefusedWithWhereItBelongs)
{
	EXPECT_EQ(fusionOptionsError("[CLaserStereoFusion]\nz_max = 4\n"),
		"<memory>: [CLaserStereoFusion] z_max: unknown key (it belongs in [FocusedEpipolarSearch])");
	EXPECT_EQ(fusionOptionsError("[ScanFusion]\nwindow_size = 9\n"),
		"<memory>: [ScanFusion] window_size: unknown key (it belongs in [ModelEvaluator])");
	// Misspelt too.
	EXPECT_EQ(fusionOptionsError("[CLaserStereoFusion]\nzz_max = 4\n"),
		"<memory>: [CLaserStereoFusion] zz_max: unknown key (did you mean [FocusedEpipolarSearch] z_max?)");
}

TEST(Options, AMisspeltSectionIsRefusedWithTheSectionLikelyMeant)
{
	EXPECT_EQ(fusionOptionsError("[FocusedEpipolarSerch]\nz_max = 4\n"),
		"<memory>: [FocusedEpipolarSerch]: unknown section (did you mean 'FocusedEpipolarSearch'?)");
}

// Found by tests/fuzz/fuzz_ini_options: MRPT's own INI preprocessor refuses
// an undefined ${name}; its exception (a banner, the message, a call stack)
// reached the apps as "internal error: MRPT exception ====", status 1.
TEST(Options, AFileMrptsPreprocessorRefusesIsAnInputErrorWithItsLine)
{
	expectIniRefused("undefined_variable.ini", "[CLaserStereoFusion]\nrobot_height = ${NOT_DEFINED}\n",
		"Line 2: Unknown variable `${NOT_DEFINED}`");
}

TEST(Options, ALineEndingInABackslashGoesOnOnTheNextAsInMrpt)
{
	// MRPT's own navigator examples write long formulas over several lines.
	const std::string path = testing::TempDir() + "continued.ini";
	std::ofstream(path) << "[CLaserStereoFusion]\nrobot_height = \\\n   1.5\nfloor_height = 0.25\n";
	const auto ini = lvf::common::openIniFile(path);
	lvf::fusion::CLaserStereoFusion::TOptions options;
	options.loadFromConfigFile(*ini, "CLaserStereoFusion");
	EXPECT_DOUBLE_EQ(options.band.high, 1.5);
	EXPECT_DOUBLE_EQ(options.floorHeight, 0.25);
	std::remove(path.c_str());
}

TEST(Options, AKeyGivenTwiceInASectionIsRefusedNamingBothLines)
{
	// MRPT would keep the last without a word.
	expectIniRefused("twice.ini",
		"[CLaserStereoFusion]\nrobot_height = \\\n  1.5\n; more\n[ScanFusion]\nmin_points = 3\n"
		"[CLaserStereoFusion]\nrobot_height = 1.2\n",
		"line 8: [CLaserStereoFusion] robot_height: given twice (first on line 2)");
}

TEST(Options, TheLinesAreCheckedAsMrptReadsThem)
{
	const std::string path = ::testing::TempDir() + "as_mrpt.ini";
	auto accepted = [&](const std::string& text) {
		std::ofstream(path) << text;
		EXPECT_NO_THROW(lvf::common::openIniFile(path)) << text;
		std::remove(path.c_str());
	};
	// A '\' before a blank does not continue the line (nor on an @define):
	// the next section header stays a header, so no key repeats.
	accepted("[ScanFusion]\nmin_points = 3 \\ \n[CLaserStereoFusion]\nmin_points = 4\n");
	accepted("@define X 1 \\\n[ScanFusion]\nmin_points = 3\n");
	accepted("\xEF\xBB\xBF[ScanFusion]\r\nmin_points = 3\r\n");	 // a UTF-8 mark, CRLF lines
	// Keys and sections compare as MRPT compares them, case aside.
	expectIniRefused("case.ini", "[ScanFusion]\nmin_points = 3\n[scanfusion]\nMIN_POINTS = 4\n",
		"line 4: [scanfusion] MIN_POINTS: given twice (first on line 2)");
}

TEST(Options, AnMrptExceptionsMessageIsItsLineWithoutBannerOrCallStack)
{
	const std::runtime_error mrpt("==== MRPT exception ====\nLine 2: Unknown variable\nCall stack backtrace:\n[0 ] 0x1\n");
	EXPECT_EQ(lvf::common::exceptionMessage(mrpt), "Line 2: Unknown variable");
	const std::runtime_error labelled("==== MRPT exception ====\nfile.cpp:10: Message: bad value\nmore\n");
	EXPECT_EQ(lvf::common::exceptionMessage(labelled), "bad value");
	EXPECT_EQ(lvf::common::exceptionMessage(std::runtime_error("plain")), "plain");
}
