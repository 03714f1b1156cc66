#include <lvfusion/common/InputError.h>
#include <lvfusion/common/WrittenFiles.h>
#include <opencv2/imgcodecs.hpp>

namespace lvf::common
{
void requireWritten(bool written, const std::string& path)
{
	if (!written) throw InputError(path, "", "cannot be written (disk full?)");
}

void writeImage(const std::string& path, const cv::Mat& image)
{
	bool written = false;
	try
	{
		written = cv::imwrite(path, image);
	}
	catch (const cv::Exception&)
	{
		// OpenCV's encoders throw on some failures and return false on others.
	}
	requireWritten(written, path);
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
