#include <lvfusion/middlebury/MiddleburyScene.h>
#include <lvfusion/middlebury/PfmFile.h>

#include <lvfusion/common/InputError.h>
#include <mrpt/core/format.h>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <filesystem>

using lvf::common::InputError;
namespace fs = std::filesystem;

namespace lvf::middlebury
{
namespace
{
void checkSize(const std::string& path, int cols, int rows, const MiddleburyCalib& calib)
{
	if (cols != calib.width || rows != calib.height)
		throw InputError(path, "", mrpt::format(
			"%dx%d pixels, but calib.txt says width %d, height %d", cols, rows,
			calib.width, calib.height));
}

mrpt::img::CImage loadImage(const std::string& path, const MiddleburyCalib& calib)
{
	mrpt::img::CImage image;
	if (!image.loadFromFile(path)) throw InputError(path, "", "cannot read image");
	checkSize(path, static_cast<int>(image.getWidth()), static_cast<int>(image.getHeight()), calib);
	return image;
}
}  // namespace

std::string MiddleburyScene::file(const std::string& fileName) const
{
	return (fs::path(dir) / fileName).string();
}

MiddleburyScene loadMiddleburyScene(const std::string& dir)
{
	if (!fs::is_directory(dir))
		throw InputError(dir, "", fs::exists(dir) ? "is a file, not a scene folder" : "scene folder not found");
	MiddleburyScene s;
	s.dir = dir;
	// Absolute, so that "." and ".." have a name (the outputs are named by it).
	const fs::path p = fs::absolute(dir).lexically_normal();
	// "data/Motorcycle/" has an empty filename(): take its parent's.
	s.name = (p.has_filename() ? p.filename() : p.parent_path().filename()).string();
	// Existence first, so that a half-copied folder names the file it lacks.
	for (const char* f : {"calib.txt", "im0.png", "im1.png", "disp0GT.pfm", "mask0nocc.png"})
		if (!fs::is_regular_file(s.file(f))) throw InputError(s.file(f), "", "file not found");

	s.calib = readMiddleburyCalib(s.file("calib.txt"));
	s.left = loadImage(s.file("im0.png"), s.calib);
	s.right = loadImage(s.file("im1.png"), s.calib);
	s.disparity = readPfm(s.file("disp0GT.pfm"));
	checkSize(s.file("disp0GT.pfm"), s.disparity.cols, s.disparity.rows, s.calib);
	s.mask = cv::imread(s.file("mask0nocc.png"), cv::IMREAD_GRAYSCALE);
	if (s.mask.empty()) throw InputError(s.file("mask0nocc.png"), "", "cannot read image");
	checkSize(s.file("mask0nocc.png"), s.mask.cols, s.mask.rows, s.calib);

	// README (shared data): Z = baseline * f / (d + doffs),
	// X = (u - cx0) Z / f, Y = (v - cy) Z / f.
	const auto& c = s.calib;
	s.points.reserve(static_cast<size_t>(c.width) * static_cast<size_t>(c.height));
	for (int v = 0; v < c.height; v++)
		for (int u = 0; u < c.width; u++)
		{
			const float d = s.disparity.at<float>(v, u);
			if (!std::isfinite(d) || s.mask.at<uint8_t>(v, u) == 0 || !(d + c.doffs > 0))
			{
				s.unknownPixels++;
				continue;
			}
			const double z = c.depth(d);
			s.points.push_back({u, v, {(u - c.cx0) * z / c.f, (v - c.cy) * z / c.f, z}});
		}
	return s;
}

}  // namespace lvf::middlebury
