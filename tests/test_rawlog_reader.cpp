// RawlogReader reads what MRPT's own reader reads, object for object and
// byte for byte -- a rawlog as MRPT writes it (one zlib stream), as
// lvfusion writes it (several gzip members), not compressed, or with bytes
// after its last member, and the real logs at hand -- though it inflates
// with igzip (GzipInputFile.h); and a rawlog cut short or corrupted is one
// InputError naming the record.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogReader.h>
#include <lvfusion/common/RawlogWriter.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/archiveFrom_std_vector.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace lvf::simulation;
namespace fs = std::filesystem;

namespace
{
using Bytes = std::vector<uint8_t>;

Bytes serialized(const mrpt::serialization::CSerializable& object)
{
	Bytes bytes;
	auto archive = mrpt::serialization::archiveFrom(bytes);
	archive << object;
	return bytes;
}

/** Every object of the file as RawlogReader reads it, serialized again;
 * `refused`: whether it stopped at an InputError rather than at the file's
 * end (without it, the InputError is thrown on). */
std::vector<Bytes> readByLvfusion(const std::string& path, bool* refused = nullptr)
{
	std::vector<Bytes> out;
	if (refused) *refused = false;
	try
	{
		lvf::common::RawlogReader reader(path);
		while (auto object = reader.next()) out.push_back(serialized(*object));
	}
	catch (const lvf::common::InputError&)
	{
		if (!refused) throw;
		*refused = true;
	}
	return out;
}

/** The same, as MRPT's own gzip reader reads them; `refused`: whether it
 * stopped at an object it could not read rather than at the file's end. */
std::vector<Bytes> readByMrpt(const std::string& path, bool* refused = nullptr)
{
	std::vector<Bytes> out;
	mrpt::io::CFileGZInputStream in(path);
	auto archive = mrpt::serialization::archiveFrom(in);
	if (refused) *refused = false;
	try
	{
		for (;;) out.push_back(serialized(*archive.ReadObject()));
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
	}
	catch (const std::exception&)
	{
		if (!refused) throw;
		*refused = true;
	}
	return out;
}

Bytes fileBytes(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	return Bytes((std::istreambuf_iterator<char>(in)), {});
}

void writeBytes(const std::string& path, const Bytes& bytes)
{
	std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

class RawlogReaderFiles : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		m_dir = fs::temp_directory_path() / ("lvf_rawlog_reader_" + std::to_string(::getpid()));
		fs::create_directories(m_dir);
		World world = loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
		world.path.resize(3);
		CStereoLaserSimulator sim(world, CStereoLaserSimulator::TOptions());
		for (int k = 0; k < 3; k++)
		{
			const auto f = sim.simulateNextFrame(false);
			m_objects.push_back(f.scan);
			m_objects.push_back(f.stereo);
		}
	}
	void TearDown() override { fs::remove_all(m_dir); }

	std::string path(const std::string& name) const { return (m_dir / name).string(); }
	/** The objects, each as MRPT's archive writes it. */
	std::vector<Bytes> expected() const
	{
		std::vector<Bytes> out;
		for (const auto& o : m_objects) out.push_back(serialized(*o));
		return out;
	}
	/** The objects written by lvfusion's writer (gzip members). */
	std::string writtenByLvfusion(const std::string& name) const
	{
		lvf::common::RawlogWriter writer(path(name), lvf::common::RawlogFormat::Observations);
		for (const auto& o : m_objects) writer.appendEntry(*o);
		writer.close();
		return path(name);
	}

	fs::path m_dir;
	std::vector<mrpt::serialization::CSerializable::Ptr> m_objects;
};
}  // namespace

TEST_F(RawlogReaderFiles, ReadsALogAsMrptWritesIt)
{
	const std::string file = path("mrpt.rawlog");
	{
		mrpt::io::CFileGZOutputStream out(file);  // zlib: one gzip stream
		auto archive = mrpt::serialization::archiveFrom(out);
		for (const auto& o : m_objects) archive << *o;
	}
	EXPECT_EQ(readByLvfusion(file), expected());
	EXPECT_EQ(readByMrpt(file), expected());
}

TEST_F(RawlogReaderFiles, ReadsALogAsLvfusionWritesIt)
{
	const std::string file = writtenByLvfusion("members.rawlog");
	EXPECT_EQ(readByLvfusion(file), expected());
	EXPECT_EQ(readByMrpt(file), expected());
}

TEST_F(RawlogReaderFiles, ReadsALogNotCompressed)
{
	const std::string file = path("plain.rawlog");
	{
		mrpt::io::CFileOutputStream out(file);
		auto archive = mrpt::serialization::archiveFrom(out);
		for (const auto& o : m_objects) archive << *o;
	}
	EXPECT_EQ(readByLvfusion(file), expected());
	EXPECT_EQ(readByMrpt(file), expected());
}

TEST_F(RawlogReaderFiles, IgnoresBytesAfterTheLastMemberAsMrptDoes)
{
	Bytes bytes = fileBytes(writtenByLvfusion("members.rawlog"));
	for (char c : std::string("not gzip")) bytes.push_back(uint8_t(c));
	writeBytes(path("trailing.rawlog"), bytes);
	EXPECT_EQ(readByLvfusion(path("trailing.rawlog")), expected());
	EXPECT_EQ(readByMrpt(path("trailing.rawlog")), expected());
}

TEST_F(RawlogReaderFiles, ReadsAMemberHeaderWithAFileNameAndAnEmptyMember)
{
	// What `gzip log.rawlog` writes: a header that names the file (FNAME,
	// RFC 1952), here before an empty member and then lvfusion's members.
	const Bytes members = fileBytes(writtenByLvfusion("members.rawlog"));
	Bytes bytes = {0x1f, 0x8b, 8, 0x08, 0, 0, 0, 0, 0, 3};	 // deflate, FNAME, no time, Unix
	for (char c : std::string("log.rawlog")) bytes.push_back(uint8_t(c));
	bytes.push_back(0);
	for (uint8_t b : {3, 0, 0, 0, 0, 0, 0, 0, 0, 0}) bytes.push_back(b);  // an empty final block, CRC 0, size 0
	bytes.insert(bytes.end(), members.begin(), members.end());
	writeBytes(path("named.rawlog"), bytes);
	EXPECT_EQ(readByLvfusion(path("named.rawlog")), expected());
	EXPECT_EQ(readByMrpt(path("named.rawlog")), expected());
}

TEST_F(RawlogReaderFiles, ReadsMembersWhoseHeadersStraddleTheReadBuffersEdges)
{
	// 20,000 empty members (400 kB, more than the reader takes from the file
	// at a time) after a first one 0 to 19 bytes longer: between them, every
	// position of a member's header across the edge of a read.
	const Bytes members = fileBytes(writtenByLvfusion("members.rawlog"));
	const Bytes empty = {0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 3, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0};
	for (int extra = 0; extra < 20; extra++)
	{
		Bytes bytes = {0x1f, 0x8b, 8, 0x08, 0, 0, 0, 0, 0, 3};	// a named member
		bytes.insert(bytes.end(), size_t(extra), uint8_t('x'));
		for (uint8_t b : {0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0}) bytes.push_back(b);
		for (int k = 0; k < 20000; k++) bytes.insert(bytes.end(), empty.begin(), empty.end());
		bytes.insert(bytes.end(), members.begin(), members.end());
		writeBytes(path("straddle.rawlog"), bytes);
		EXPECT_EQ(readByLvfusion(path("straddle.rawlog")), expected()) << extra;
	}
}

TEST_F(RawlogReaderFiles, ALogCutShortOrCorruptedIsAnErrorNamingTheRecord)
{
	const Bytes whole = fileBytes(writtenByLvfusion("members.rawlog"));
	const std::string cut = path("cut.rawlog"), corrupt = path("corrupt.rawlog");
	writeBytes(cut, Bytes(whole.begin(), whole.begin() + long(whole.size() * 6 / 10)));
	Bytes spoilt = whole;
	for (size_t i = whole.size() / 3; i < whole.size() / 3 + 64; i++) spoilt[i] ^= 0x5a;
	writeBytes(corrupt, spoilt);
	for (const auto& file : {cut, corrupt})
	{
		try
		{
			readByLvfusion(file);
			ADD_FAILURE() << file << ": no error";
		}
		catch (const lvf::common::InputError& e)
		{
			EXPECT_NE(std::string(e.what()).find(file + ": record "), std::string::npos) << e.what();
			EXPECT_NE(std::string(e.what()).find("corrupt, truncated or not a rawlog"), std::string::npos) << e.what();
		}
	}
}

TEST(RawlogReaderRealLogs, ReadsEachAsMrptDoes)
{
	// The laser logs beside the project and MRPT's own datasets (mrpt-common):
	// one zlib stream each, and one of MRPT's not compressed.
	std::vector<fs::path> logs;
	for (const std::string& dir : {std::string(LVF_SHARED_DATA_DIR) + "/laser", std::string("/usr/share/mrpt/datasets")})
		if (fs::is_directory(dir))
			for (const auto& e : fs::directory_iterator(dir))
				if (e.path().extension() == ".rawlog") logs.push_back(e.path());
	if (logs.empty()) GTEST_SKIP() << "no real logs here";
	for (const auto& log : logs)
	{
		bool mrptRefused = false;
		const auto mrpt = readByMrpt(log.string(), &mrptRefused);
		bool oursRefused = false;
		const auto ours = readByLvfusion(log.string(), &oursRefused);
		EXPECT_EQ(ours.size(), mrpt.size()) << log;
		EXPECT_TRUE(ours == mrpt) << log;
		EXPECT_EQ(oursRefused, mrptRefused) << log;
	}
}

TEST(RawlogName, IsTheFileNameWithoutItsRawlogExtensions)
{
	using lvf::common::rawlogName;
	EXPECT_EQ(rawlogName("data/run.rawlog"), "run");
	EXPECT_EQ(rawlogName("data/run.rawlog.gz"), "run");  // a common name for MRPT's logs
	EXPECT_EQ(rawlogName("run.gz"), "run");
	EXPECT_EQ(rawlogName("/logs/two.parts.rawlog"), "two.parts");
	EXPECT_EQ(rawlogName("run.bin"), "run");
	EXPECT_EQ(rawlogName("run"), "run");
}
