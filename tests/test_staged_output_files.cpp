// What moving a run's outputs into place may touch: only what the run
// wrote. A folder the user already has is merged into, never replaced (only
// an earlier run's files of the kinds this run writes there go); a
// name that would leave the output folder is refused before anything is
// written; a name that cannot be a file's is refused where it is given.

#include <gtest/gtest.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/StagedOutputFiles.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;
using lvf::common::InputError;
using lvf::common::StagedOutputFiles;

/** A fresh folder of its own for each test, removed afterwards. */
class StagedOutputs : public testing::Test
{
   protected:
	void SetUp() override
	{
		m_root = fs::path(testing::TempDir()) /
			("staged_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
			 std::to_string(::getpid()));
		fs::remove_all(m_root);
		fs::create_directories(m_root);
	}
	void TearDown() override { fs::remove_all(m_root); }

	static void write(const fs::path& path, const std::string& text)
	{
		fs::create_directories(path.parent_path());
		std::ofstream(path) << text;
	}
	static std::string read(const fs::path& path)
	{
		std::ifstream in(path);
		return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
	}

	fs::path m_root;
};

TEST_F(StagedOutputs, AFolderOfTheSameNameIsMergedIntoNotReplaced)
{
	const fs::path out = m_root / "out";
	write(out / "run_navlog" / "notes.txt", "the user's");
	write(out / "run_navlog" / "log_000.reactivenavlog", "an older run's");
	StagedOutputFiles files(out.string());
	write(files.stage("run_navlog/log_000.reactivenavlog"), "this run's");
	write(files.stage("run_metrics.txt"), "metrics");
	files.commit();
	EXPECT_EQ(read(out / "run_navlog" / "notes.txt"), "the user's");
	EXPECT_EQ(read(out / "run_navlog" / "log_000.reactivenavlog"), "this run's");
	EXPECT_EQ(read(out / "run_metrics.txt"), "metrics");
}

// An earlier, longer run's files in a folder of the run's would be read as
// this run's (NAME_depth/ holding depth maps of frames the rawlog has not).
TEST_F(StagedOutputs, AnEarlierRunsFilesOfTheSameKindInARunsFolderGo)
{
	const fs::path out = m_root / "out";
	for (const char* frame : {"000000.pfm", "000001.pfm", "000002.pfm"})
		write(out / "run_depth" / frame, "an earlier run's");
	write(out / "run_depth" / "notes.txt", "the user's");
	write(out / "run_depth" / "README", "the user's, with no extension");
	write(out / "run_depth" / "kept" / "000001.pfm", "the user's, in a folder of their own");
	write(out / "other.pfm", "beside the run's folder");
	StagedOutputFiles files(out.string());
	write(files.stage("run_depth/000000.pfm"), "this run's");
	write(files.stage("run_depth/LOG"), "this run's, with no extension");
	files.commit();
	EXPECT_EQ(read(out / "run_depth" / "000000.pfm"), "this run's");
	EXPECT_FALSE(fs::exists(out / "run_depth" / "000001.pfm"));
	EXPECT_FALSE(fs::exists(out / "run_depth" / "000002.pfm"));
	EXPECT_EQ(read(out / "run_depth" / "notes.txt"), "the user's");
	EXPECT_EQ(read(out / "run_depth" / "README"), "the user's, with no extension");
	EXPECT_TRUE(fs::exists(out / "run_depth" / "kept" / "000001.pfm"));
	EXPECT_EQ(read(out / "other.pfm"), "beside the run's folder");
}

// A run's folder that is a link to another place (the user's archive) is
// merged into, but nothing there is removed: it is not the run's.
TEST_F(StagedOutputs, ARunsFolderLinkedElsewhereIsNeverPruned)
{
	const fs::path out = m_root / "out", archive = m_root / "archive";
	for (const char* frame : {"000000.pfm", "000001.pfm", "mine.pfm"}) write(archive / frame, "the user's");
	fs::create_directories(out);
	fs::create_directory_symlink(archive, out / "run_depth");
	StagedOutputFiles files(out.string());
	write(files.stage("run_depth/000000.pfm"), "this run's");
	files.commit();
	EXPECT_EQ(read(archive / "000000.pfm"), "this run's");
	EXPECT_EQ(read(archive / "000001.pfm"), "the user's");
	EXPECT_EQ(read(archive / "mine.pfm"), "the user's");
}

TEST_F(StagedOutputs, ANameThatLeavesTheOutputFolderIsRefused)
{
	const fs::path out = m_root / "parent" / "out";
	write(m_root / "parent" / "keep.txt", "the user's");
	StagedOutputFiles files(out.string());
	for (const std::string name : {"../escape.rawlog", "a/../../b.txt", "./x.csv", "/tmp/abs.txt", ""})
		EXPECT_THROW(files.stage(name), InputError) << "'" << name << "'";
	write(files.stage("fine.txt"), "fine");
	files.commit();
	EXPECT_EQ(read(m_root / "parent" / "keep.txt"), "the user's");
	EXPECT_EQ(read(out / "fine.txt"), "fine");
	EXPECT_FALSE(fs::exists(m_root / "parent" / "escape.rawlog"));
}

TEST_F(StagedOutputs, AFileWhereTheUserHasAFolderIsAnErrorAndTheFolderStays)
{
	const fs::path out = m_root / "out";
	write(out / "run.rawlog" / "precious.txt", "the user's");
	StagedOutputFiles files(out.string());
	write(files.stage("run.rawlog"), "a log");
	EXPECT_THROW(files.commit(), InputError);
	EXPECT_EQ(read(out / "run.rawlog" / "precious.txt"), "the user's");
}

TEST_F(StagedOutputs, AClashAnywhereIsFoundBeforeAnythingIsMoved)
{
	// The user has a file where the run writes a folder: nothing of the run
	// is moved, not even the entries before the clash.
	const fs::path out = m_root / "out";
	write(out / "run_poses.txt", "an older run's");
	write(out / "run_navlog", "a file of the user's");
	StagedOutputFiles files(out.string());
	write(files.stage("run_poses.txt"), "this run's");
	write(files.stage("run_navlog/log_000.reactivenavlog"), "this run's");
	EXPECT_THROW(files.commit(), InputError);
	EXPECT_EQ(read(out / "run_poses.txt"), "an older run's");
	EXPECT_EQ(read(out / "run_navlog"), "a file of the user's");
}

TEST_F(StagedOutputs, AWithdrawnOutputIsNotWritten)
{
	const fs::path out = m_root / "out";
	StagedOutputFiles files(out.string());
	write(files.stage("run.rawlog"), "");
	fs::create_directories(files.stage("run_navlog/"));
	write(files.stage("run_metrics.txt"), "metrics");
	files.withdraw("run.rawlog");
	files.withdraw("run_navlog");
	for (const std::string outside : {"", "../out", "/tmp", "a/../.."})  // never outside the staging folder
		EXPECT_THROW(files.withdraw(outside), InputError) << "'" << outside << "'";
	files.commit();
	EXPECT_FALSE(fs::exists(out / "run.rawlog"));
	EXPECT_FALSE(fs::exists(out / "run_navlog"));
	EXPECT_EQ(read(out / "run_metrics.txt"), "metrics");
}

TEST(OutputNames, APlainFileNameHasNoFolderInIt)
{
	using lvf::common::isPlainFileName;
	for (const std::string name : {"box_room", "random_7", "run.v2", "..a", "a b"})
		EXPECT_TRUE(isPlainFileName(name)) << name;
	for (const std::string name : {"", ".", "..", "../escape", "a/b", "/abs", "dir/"})
		EXPECT_FALSE(isPlainFileName(name)) << name;
}

TEST_F(StagedOutputs, AnOutputFolderNamedLikeARawlogIsRefusedUnlessItIsAFolderAlready)
{
	using lvf::common::rejectRawlogNamedFolder;
	EXPECT_THROW(rejectRawlogNamedFolder((m_root / "fused.rawlog").string(), "--outdir", ""), InputError);
	EXPECT_THROW(rejectRawlogNamedFolder((m_root / "fused.rawlog.gz").string(), "--outdir", ""), InputError);
	EXPECT_NO_THROW(rejectRawlogNamedFolder((m_root / "results").string(), "--outdir", ""));
	fs::create_directories(m_root / "old.rawlog");
	EXPECT_NO_THROW(rejectRawlogNamedFolder((m_root / "old.rawlog").string(), "--outdir", ""));
}

}  // namespace
