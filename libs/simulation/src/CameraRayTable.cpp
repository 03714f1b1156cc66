#include <lvfusion/common/OpenCvCamera.h>
#include <lvfusion/simulation/CameraRayTable.h>
#include <opencv2/calib3d.hpp>

#include <algorithm>

namespace lvf::simulation
{
CameraRayTable::CameraRayTable(
	const mrpt::img::TCamera& camera, int supersampling)
	: m_cols(static_cast<int>(camera.ncols) * supersampling),
	  m_rows(static_cast<int>(camera.nrows) * supersampling),
	  m_supersampling(supersampling)
{
	// Sample (i, j) sits at pixel coordinate (i + 0.5) / s - 0.5: the pixel
	// centres are the integer coordinates, as in MRPT and OpenCV.
	std::vector<cv::Point2d> samples;
	samples.reserve(static_cast<size_t>(m_cols) * m_rows);
	const double s = supersampling;
	for (int j = 0; j < m_rows; j++)
		for (int i = 0; i < m_cols; i++)
			samples.emplace_back((i + 0.5) / s - 0.5, (j + 0.5) / s - 0.5);

	const std::vector<double> D = lvf::common::openCvDistortion(camera);
	std::vector<cv::Point2d> rays;
	if (D.empty())
	{
		rays.reserve(samples.size());
		for (const auto& p : samples)
			rays.emplace_back(
				(p.x - camera.cx()) / camera.fx(),
				(p.y - camera.cy()) / camera.fy());
	}
	else
	{
		// Tight criteria: the default 5 iterations leave ~0.1 px errors at the
		// corners of a strongly distorted image.
		cv::undistortPoints(
			samples, rays, lvf::common::openCvCameraMatrix(camera), D, cv::noArray(),
			cv::noArray(),
			cv::TermCriteria(
				cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
	}
	m_x.resize(rays.size());
	m_y.resize(rays.size());
	for (size_t k = 0; k < rays.size(); k++)
	{
		m_x[k] = static_cast<float>(rays[k].x);
		m_y[k] = static_cast<float>(rays[k].y);
	}

	for (int r0 = 0; r0 < m_rows; r0 += kTileSize)
		for (int c0 = 0; c0 < m_cols; c0 += kTileSize)
		{
			Tile t{c0, r0, std::min(c0 + kTileSize, m_cols),
				   std::min(r0 + kTileSize, m_rows), 1e9f, -1e9f, 1e9f, -1e9f};
			for (int r = t.row0; r < t.row1; r++)
				for (int c = t.col0; c < t.col1; c++)
				{
					t.xMin = std::min(t.xMin, rayX(c, r));
					t.xMax = std::max(t.xMax, rayX(c, r));
					t.yMin = std::min(t.yMin, rayY(c, r));
					t.yMax = std::max(t.yMax, rayY(c, r));
				}
			m_tiles.push_back(t);
		}
}

}  // namespace lvf::simulation
