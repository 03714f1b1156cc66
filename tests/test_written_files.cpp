// Outputs that could not be written are errors naming the file, not short
// files the run reports as written. /dev/full stands for a full disk: it
// takes a file's opening and fails every write that reaches it. Most cases
// write less than the writer buffers, so that only closing the file can
// tell -- the case MRPT's own gzip stream stays silent about; a rawlog's
// entries are also written on a thread of their own, whose failure the
// next entry or the close must report.

#include <gtest/gtest.h>
#include <lvfusion/common/GridOutputs.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/WrittenFiles.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <unistd.h>

namespace
{
using lvf::common::InputError;

const std::string kFullDisk = "/dev/full";

/** `write` throws an InputError whose line names `path`. */
void expectErrorNaming(const std::string& path, const std::function<void()>& write)
{
	try
	{
		write();
		FAIL() << "writing " << path << " succeeded";
	}
	catch (const InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
		EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
	}
}

mrpt::obs::CObservationOdometry::Ptr odometryReading()
{
	auto odo = std::make_shared<mrpt::obs::CObservationOdometry>();
	odo->sensorLabel = "ODOMETRY";
	odo->timestamp = mrpt::Clock::now();
	odo->odometry = mrpt::poses::CPose2D(1, 2, 0.3);
	return odo;
}

class WrittenFiles : public testing::Test
{
   protected:
	void SetUp() override
	{
		if (!std::filesystem::exists(kFullDisk)) GTEST_SKIP() << "no /dev/full on this system";
	}
};
}  // namespace

TEST_F(WrittenFiles, ARawlogThatDoesNotReachTheDiskFailsOnClose)
{
	lvf::common::RawlogWriter writer(kFullDisk, lvf::common::RawlogFormat::Observations);
	writer.appendEntry(*odometryReading());  // a few bytes: buffered by zlib
	expectErrorNaming(kFullDisk, [&] { writer.close(); });
}

TEST_F(WrittenFiles, ARawlogThatRunsOutOfDiskAfterSomeEntriesIsAnError)
{
	// Entries far larger than zlib buffers: the writing thread's first
	// write to the disk fails, and a later entry or the close says so.
	lvf::common::RawlogWriter writer(kFullDisk, lvf::common::RawlogFormat::Observations);
	cv::Mat1b noise(480, 640);
	cv::randu(noise, 0, 256);  // next to incompressible
	mrpt::obs::CObservationImage picture;
	picture.image = mrpt::img::CImage(noise, mrpt::img::DEEP_COPY);
	expectErrorNaming(kFullDisk, [&] {
		for (int k = 0; k < 50; k++) writer.appendEntry(picture);
		writer.close();
	});
}

TEST_F(WrittenFiles, AGridThatDoesNotReachTheDiskIsAnError)
{
	const mrpt::maps::COccupancyGridMap2D grid(-1, 1, -1, 1, 0.1f);
	expectErrorNaming(kFullDisk, [&] { lvf::common::saveGrid(grid, kFullDisk); });
}

TEST_F(WrittenFiles, TextAndPicturesThatDoNotReachTheDiskAreErrors)
{
	expectErrorNaming(kFullDisk, [&] { lvf::common::writeTextFile(kFullDisk, "frame,recall\n0,0.9\n"); });
	lvf::common::OutputFile csv(kFullDisk);
	csv << "frame,recall\n";
	expectErrorNaming(kFullDisk, [&] { csv.close(); });
	const std::string png = "/nonexistent-folder/picture.png";
	expectErrorNaming(png, [&] { lvf::common::writeImage(png, cv::Mat1b(8, 8, uint8_t(100))); });
}

TEST(SavedGrid, IsWhatMrptsGzipStreamReads)
{
	// The same archive, read back by MRPT's own reader.
	const std::string path = testing::TempDir() + "/written_files_" + std::to_string(::getpid()) + ".gz";
	mrpt::maps::COccupancyGridMap2D grid(-1, 1, -2, 2, 0.1f);
	grid.setCell(3, 4, 0.1f);
	lvf::common::saveGrid(grid, path);
	mrpt::io::CFileGZInputStream in(path);
	mrpt::maps::COccupancyGridMap2D back;
	mrpt::serialization::archiveFrom(in) >> back;
	EXPECT_EQ(back.getSizeX(), grid.getSizeX());
	EXPECT_EQ(back.getSizeY(), grid.getSizeY());
	EXPECT_FLOAT_EQ(back.getCell(3, 4), grid.getCell(3, 4));
	std::filesystem::remove(path);
}

TEST(StagedOutputFiles, AnErrorNamesTheFileWhereTheUserWillLookForIt)
{
	// Files are written into a hidden staging folder and moved into the
	// output folder at the end; an error while writing one names it in the
	// output folder.
	const std::string out = testing::TempDir() + "/staged_names_" + std::to_string(::getpid());
	lvf::common::StagedOutputFiles files(out);
	const std::string staged = files.stage("run_frames.csv");
	const std::string message = InputError(staged, "", "cannot be written (disk full?)").what();
	const std::string shown = lvf::common::withOutputPaths(message);
	EXPECT_EQ(shown, out + "/run_frames.csv: cannot be written (disk full?)") << message;
	std::filesystem::remove_all(out);
}
