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
	std::ofstream out(path, std::ios::binary);
	out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
	closeWritten(out, path);
}

void closeWritten(std::ofstream& out, const std::string& path)
{
	out.close();
	requireWritten(!out.fail(), path);
}

void writeTextFile(const std::string& path, const std::string& text)
{
	std::ofstream out(path);
	out << text;
	closeWritten(out, path);
}

}  // namespace lvf::common
