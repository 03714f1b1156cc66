#pragma once
// The viewing ray of every (sub-)pixel of a calibrated camera, computed once.
//
// Images are rendered *distorted*, exactly as the stored calibration says: for
// the centre of each output (sub-)pixel we ask OpenCV's undistortPoints for the
// normalised ray (x, y, 1) that the lens maps onto it. Rays are grouped into
// square tiles with the bounds of their normalised coordinates, so the
// renderer can skip boxes that cannot appear in a tile.

#include <mrpt/img/TCamera.h>

#include <vector>

namespace lvf::simulation
{
class CameraRayTable
{
   public:
	static constexpr int kTileSize = 16;  //!< tile side, in samples

	/** @param supersampling samples per pixel along each axis (odd). */
	CameraRayTable(const mrpt::img::TCamera& camera, int supersampling);

	int sampleCols() const { return m_cols; }
	int sampleRows() const { return m_rows; }
	int supersampling() const { return m_supersampling; }
	/** Normalised ray (x, y, 1) in the camera frame of sample (col, row). */
	float rayX(int col, int row) const { return m_x[row * m_cols + col]; }
	float rayY(int col, int row) const { return m_y[row * m_cols + col]; }

	struct Tile
	{
		int col0, row0, col1, row1;	 //!< sample range [col0, col1) x [row0, row1)
		float xMin, xMax, yMin, yMax;  //!< bounds of the rays inside
	};
	const std::vector<Tile>& tiles() const { return m_tiles; }

   private:
	int m_cols, m_rows, m_supersampling;
	std::vector<float> m_x, m_y;
	std::vector<Tile> m_tiles;
};

}  // namespace lvf::simulation
