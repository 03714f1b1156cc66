#include "TrajectoryImage.h"

#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <mrpt/img/CImage.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace lvf::apps
{
namespace
{
/** A strip under the picture saying what each colour is, on as many lines
 * as its width needs. */
cv::Mat withLegend(const cv::Mat& canvas)
{
	enum class Mark { Square, Stroke, Ring };
	struct Item
	{
		Mark mark;
		cv::Scalar colour;
		std::string text;
	};
	const std::vector<Item> items{
		{Mark::Square, cv::Scalar::all(0), "obstacle in the band (truth)"},
		{Mark::Square, cv::Scalar(0, 0, 120), "robot's obstacle cell on it"},
		{Mark::Square, cv::Scalar(80, 170, 255), "... where there is none"},
		{Mark::Stroke, cv::Scalar(0, 0, 255), "path"},
		{Mark::Stroke, cv::Scalar(200, 0, 200), "last plan"},
		{Mark::Ring, cv::Scalar(0, 160, 0), "start"},
		{Mark::Ring, cv::Scalar(255, 0, 0), "target"}};
	constexpr int kLine = 22, kMark = 24, kSpace = 16;
	constexpr double kFont = 0.45;
	auto width = [&](const Item& i) {
		return kMark + cv::getTextSize(i.text, cv::FONT_HERSHEY_SIMPLEX, kFont, 1, nullptr).width + kSpace;
	};
	int lines = 1, lineX = 8;
	for (const auto& i : items)
	{
		if (lineX + width(i) > canvas.cols && lineX > 8) lines++, lineX = 8;
		lineX += width(i);
	}
	cv::Mat out(canvas.rows + lines * kLine + 8, canvas.cols, canvas.type(), cv::Scalar::all(255));
	canvas.copyTo(out(cv::Rect(0, 0, canvas.cols, canvas.rows)));
	int x = 8, y = canvas.rows + kLine / 2 + 4;
	for (const auto& i : items)
	{
		if (x + width(i) > canvas.cols && x > 8) y += kLine, x = 8;
		if (i.mark == Mark::Square) cv::rectangle(out, cv::Rect(x, y - 6, 12, 12), i.colour, cv::FILLED);
		if (i.mark == Mark::Stroke) cv::line(out, {x, y}, {x + 20, y}, i.colour, 2, cv::LINE_AA);
		if (i.mark == Mark::Ring) cv::circle(out, {x + 6, y}, 6, i.colour, 2, cv::LINE_AA);
		cv::putText(out, i.text, {x + kMark, y + 5}, cv::FONT_HERSHEY_SIMPLEX, kFont, cv::Scalar::all(0), 1, cv::LINE_AA);
		x += width(i);
	}
	return out;
}
}  // namespace

void writeTrajectoryImage(
	const lvf::navigation::NavigationScenario& scenario, const lvf::navigation::NavigationRun& run,
	double targetTolerance, const std::string& path)
{
	const auto truth = lvf::simulation::obstacleGrid(scenario.world, 0.01, 0.3);
	mrpt::img::CImage img;
	truth.getAsImage(img, false /* row 0 = largest y: north up */, true);
	cv::Mat canvas = img.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY);
	const int rows = canvas.rows;
	const auto px = [&](double x, double y) {
		return cv::Point(truth.x2idx(x), rows - 1 - truth.y2idx(y));
	};
	const double scale = 1.0 / truth.getResolution();
	if (run.grid)
	{
		// The robot's belief: obstacle cells it sensed, orange where truth is
		// free (phantoms), dark red over a true obstacle.
		const auto& g = run.grid->geometry();
		// A cell's side in pixels, rounded once, so cells tile without gaps.
		const int side = std::max(1, static_cast<int>(std::lround(g.getResolution() * scale)));
		for (int cy = 0; cy < int(g.getSizeY()); cy++)
			for (int cx = 0; cx < int(g.getSizeX()); cx++)
				if (run.grid->obstacle(cx, cy))
				{
					const auto p = px(g.idx2x(cx), g.idx2y(cy));
					const cv::Rect cell(p.x - side / 2, p.y - side / 2, side, side);
					const auto& c = canvas.at<cv::Vec3b>(std::clamp(p.y, 0, rows - 1), std::clamp(p.x, 0, canvas.cols - 1));
					const auto color = c[0] > 128 ? cv::Scalar(80, 170, 255) : cv::Scalar(0, 0, 120);
					cv::rectangle(canvas, cell & cv::Rect(0, 0, canvas.cols, rows), color, cv::FILLED);
				}
	}
	// The last global-guidance plan, thin violet, under the driven path.
	std::vector<cv::Point> plan;
	for (const auto& p : run.plannedPath) plan.push_back(px(p.x, p.y));
	if (plan.size() > 1) cv::polylines(canvas, plan, false, cv::Scalar(200, 0, 200), 1, cv::LINE_AA);
	const auto& m = run.metrics;
	std::vector<cv::Point> line;
	for (const auto& p : m.trajectory) line.push_back(px(p.x, p.y));
	if (line.size() > 1) cv::polylines(canvas, line, false, cv::Scalar(0, 0, 255), 2, cv::LINE_AA);
	const double r = scenario.world.robot.radius * scale;
	cv::circle(canvas, px(scenario.start.x, scenario.start.y), int(r), cv::Scalar(0, 160, 0), 2, cv::LINE_AA);
	cv::circle(canvas, px(scenario.target.x, scenario.target.y), int(targetTolerance * scale), cv::Scalar(255, 0, 0), 2, cv::LINE_AA);
	if (m.outcome == lvf::navigation::Outcome::Collision && !line.empty())
	{
		const auto c = line.back();
		const int k = int(r);
		cv::line(canvas, c - cv::Point(k, k), c + cv::Point(k, k), cv::Scalar(0, 0, 255), 3);
		cv::line(canvas, c - cv::Point(k, -k), c + cv::Point(k, -k), cv::Scalar(0, 0, 255), 3);
	}
	// Only what is drawn (the truth grid spans every box of the world, the
	// floor's too), with a margin.
	cv::Mat grey;
	cv::cvtColor(canvas, grey, cv::COLOR_BGR2GRAY);
	const int margin = 20;
	cv::Rect shown = cv::boundingRect(grey < 250);
	shown = cv::Rect(shown.x - margin, shown.y - margin, shown.width + 2 * margin, shown.height + 2 * margin) &
		cv::Rect(0, 0, canvas.cols, canvas.rows);
	if (shown.area() == 0) shown = cv::Rect(0, 0, canvas.cols, canvas.rows);
	lvf::common::writeImage(path, withLegend(canvas(shown)));
}

}  // namespace lvf::apps
