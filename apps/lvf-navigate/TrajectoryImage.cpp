#include "TrajectoryImage.h"

#include <lvfusion/simulation/GroundTruth.h>
#include <mrpt/img/CImage.h>

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace lvf::apps
{
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
		for (int cy = 0; cy < int(g.getSizeY()); cy++)
			for (int cx = 0; cx < int(g.getSizeX()); cx++)
				if (run.grid->obstacle(cx, cy))
				{
					const auto p = px(g.idx2x(cx), g.idx2y(cy));
					const int half = int(0.5 * g.getResolution() * scale);
					const cv::Rect cell(p.x - half, p.y - half, 2 * half, 2 * half);
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
	cv::imwrite(path, canvas);
}

}  // namespace lvf::apps
