#include <lvfusion/middlebury/PfmFile.h>

#include <lvfusion/common/InputError.h>
#include <mrpt/config.h>
#include <mrpt/core/format.h>
#include <mrpt/core/reverse_bytes.h>

#include <cctype>
#include <cmath>
#include <fstream>

using lvf::common::InputError;

namespace lvf::middlebury
{
namespace
{
/** The next whitespace-separated header token; the single whitespace byte
 * after it is consumed too (after the scale, pixel data starts right there). */
std::string headerToken(std::istream& in, const std::string& path, const std::string& field)
{
	std::string token;
	int c = in.get();
	while (c != EOF && std::isspace(c)) c = in.get();
	while (c != EOF && !std::isspace(c))
	{
		token += static_cast<char>(c);
		if (token.size() > 64) break;
		c = in.get();
	}
	if (token.empty() || c == EOF)
		throw InputError(path, "header: " + field, "missing (file ends in the header)");
	return token;
}

double headerNumber(std::istream& in, const std::string& path, const std::string& field)
{
	const std::string token = headerToken(in, path, field);
	try
	{
		size_t used = 0;
		const double v = std::stod(token, &used);
		if (used == token.size() && std::isfinite(v)) return v;
	}
	catch (const std::exception&)
	{
	}
	throw InputError(path, "header: " + field, "'" + token + "' is not a number");
}
}  // namespace

cv::Mat readPfm(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	if (!in) throw InputError(path, "", "cannot open PFM file");
	const std::string magic = headerToken(in, path, "type");
	if (magic == "PF")
		throw InputError(path, "header: type", "colour PFM (PF), expected one channel (Pf)");
	if (magic != "Pf") throw InputError(path, "header: type", "'" + magic + "' is not a PFM file (Pf)");
	const double width = headerNumber(in, path, "width");
	const double height = headerNumber(in, path, "height");
	for (const auto& [field, v] : {std::pair{"width", width}, std::pair{"height", height}})
		if (v < 1 || v > 65536 || v != std::floor(v))
			throw InputError(path, std::string("header: ") + field, mrpt::format("%g is not a valid size", v));
	const double scale = headerNumber(in, path, "scale");
	if (scale == 0) throw InputError(path, "header: scale", "0 (its sign must give the byte order)");

	const int w = static_cast<int>(width), h = static_cast<int>(height);
	const size_t rowBytes = static_cast<size_t>(w) * sizeof(float);
	const size_t expected = rowBytes * static_cast<size_t>(h);
	// Size first: a corrupt header must not make us allocate gigabytes.
	const auto dataStart = in.tellg();
	in.seekg(0, std::ios::end);
	const auto available = static_cast<size_t>(in.tellg() - dataStart);
	in.seekg(dataStart);
	if (available < expected)
		throw InputError(path, "pixel data", mrpt::format(
			"%zu of %zu bytes (%dx%d floats): file truncated", available, expected, w, h));
	if (available > expected)
		throw InputError(path, "pixel data", mrpt::format(
			"%zu bytes more than the %dx%d floats the header announces", available - expected, w, h));

	cv::Mat image(h, w, CV_32FC1);
	for (int y = h - 1; y >= 0; y--)  // stored bottom to top
		in.read(reinterpret_cast<char*>(image.ptr<float>(y)), static_cast<std::streamsize>(rowBytes));
	if (!in) throw InputError(path, "pixel data", "read error");
	// Negative scale: little-endian data.
	const bool littleEndianData = scale < 0;
	if (littleEndianData == static_cast<bool>(MRPT_IS_BIG_ENDIAN))
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) mrpt::reverseBytesInPlace(image.at<float>(y, x));
	return image;
}

}  // namespace lvf::middlebury
