#include "GzipMemberFile.h"

#include <lvfusion/common/GridOutputs.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace lvf::common
{
void saveGrid(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& gridmapPath)
{
	// Level 2, as the rawlogs (RawlogWriter.cpp).
	GzipMemberFile out(gridmapPath, 2);
	out.writeMember(archived(grid));
	out.close();
}

std::vector<mrpt::maps::COccupancyGridMap2D> onCommonExtent(
	const std::vector<const mrpt::maps::COccupancyGridMap2D*>& grids)
{
	std::vector<mrpt::maps::COccupancyGridMap2D> out;
	if (grids.empty()) return out;
	float xMin = grids[0]->getXMin(), xMax = grids[0]->getXMax();
	float yMin = grids[0]->getYMin(), yMax = grids[0]->getYMax();
	for (const auto* g : grids)
	{
		xMin = std::min(xMin, g->getXMin()), xMax = std::max(xMax, g->getXMax());
		yMin = std::min(yMin, g->getYMin()), yMax = std::max(yMax, g->getYMax());
	}
	for (const auto* g : grids)
	{
		out.push_back(*g);
		out.back().resizeGrid(xMin, xMax, yMin, yMax, 0.5f, false);
	}
	return out;
}

namespace
{
constexpr int kLabelHeight = 24, kGap = 10, kMargin = 10;

/** Where `picture` shows anything but the unknown grey (127). */
cv::Rect observedArea(const cv::Mat& picture)
{
	cv::Mat grey;
	if (picture.channels() == 1) grey = picture;
	else cv::cvtColor(picture, grey, cv::COLOR_BGR2GRAY);
	return cv::boundingRect(cv::abs(grey - cv::Scalar::all(127)) > 2);
}
}  // namespace

cv::Mat sideBySide(const std::vector<cv::Mat>& pictures, const std::vector<std::string>& labels, int targetSize)
{
	CV_Assert(!pictures.empty() && labels.size() == pictures.size());
	const cv::Rect whole(0, 0, pictures[0].cols, pictures[0].rows);
	cv::Rect seen;
	for (const auto& p : pictures)
	{
		CV_Assert(p.size() == pictures[0].size() && p.type() == pictures[0].type());
		const cv::Rect r = observedArea(p);
		seen = seen.area() ? (seen | r) : r;
	}
	if (!seen.area()) seen = whole;
	seen = cv::Rect(seen.x - kMargin, seen.y - kMargin, seen.width + 2 * kMargin, seen.height + 2 * kMargin) & whole;
	const int scale = std::max(1, targetSize / std::max(seen.width, seen.height));
	const int width = seen.width * scale, height = seen.height * scale;
	const int n = static_cast<int>(pictures.size());
	cv::Mat out(height + kLabelHeight, n * width + (n - 1) * kGap, pictures[0].type(), cv::Scalar::all(255));
	for (int k = 0; k < n; k++)
	{
		const int x0 = k * (width + kGap);
		cv::Mat target = out(cv::Rect(x0, kLabelHeight, width, height));
		cv::resize(pictures[static_cast<size_t>(k)](seen), target, target.size(), 0, 0, cv::INTER_NEAREST);
		cv::putText(out, labels[static_cast<size_t>(k)], {x0 + 4, kLabelHeight - 7}, cv::FONT_HERSHEY_SIMPLEX, 0.55,
			cv::Scalar::all(0), 1, cv::LINE_AA);
	}
	return out;
}

}  // namespace lvf::common
