#include <lvfusion/common/InputError.h>
#include <lvfusion/common/WrittenFiles.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <vector>

namespace lvf::common
{
void requireWritten(bool written, const std::string& path)
{
	if (!written) throw InputError(path, "", "cannot be written (disk full?)");
}

void writeImage(const std::string& path, const cv::Mat& image)
{
	// Encoded in memory, then written and checked as any file is: libpng,
	// writing the file itself, prints a line of its own before OpenCV
	// returns false, and the user should get one line.
	std::vector<uchar> bytes;
	bool encoded = false;
	try
	{
		encoded = cv::imencode(std::filesystem::path(path).extension().string(), image, bytes);
	}
	catch (const cv::Exception&)
	{
		// (an extension no encoder takes)
	}
	if (!encoded) throw InputError(path, "", "cannot be encoded as a picture of that type");
	OutputFile out(path, std::ios::binary);
	out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
	out.close();
}

void OutputFile::open(const std::string& path, std::ios::openmode mode)
{
	m_path = path;
	std::ofstream::open(path, mode);
	if (!is_open()) throw InputError(path, "", "cannot open for writing");
}

void OutputFile::close()
{
	std::ofstream::close();
	requireWritten(!fail(), m_path);
}

void writeTextFile(const std::string& path, const std::string& text)
{
	OutputFile out(path);
	out << text;
	out.close();
}

}  // namespace lvf::common
