#include "GroundTruthWriter.h"

#include <lvfusion/common/GridOutputs.h>
#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <mrpt/core/format.h>

#include <cmath>

namespace lvf::apps
{
GroundTruthWriter::GroundTruthWriter(
	lvf::common::StagedOutputFiles& files, const std::string& name,
	bool writeDepth)
	: m_files(files), m_name(name), m_writeDepth(writeDepth)
{
	m_poses.open(files.stage(name + "_gt_poses.txt"));
	m_poses << "# ground-truth robot poses: frame timestamp[s] x[m] y[m] yaw[rad]\n";
	m_truth.open(files.stage(name + "_truth_scans.csv"));
	m_seenTruth.open(files.stage(name + "_seen_truth_scans.csv"));
}

namespace
{
/** One frame's row of a truth scan file; the header before frame 0. */
void writeScanRow(
	std::ostream& out, const lvf::simulation::CStereoLaserSimulator::Frame& f, const std::vector<float>& ranges)
{
	if (f.index == 0)
	{
		out << "frame,timestamp";
		for (size_t i = 0; i < ranges.size(); i++) out << mrpt::format(",b%.2f", mrpt::RAD2DEG(f.scan->getScanAngle(i)));
		out << "\n";
	}
	out << f.index << mrpt::format(",%.6f", mrpt::Clock::toDouble(f.timestamp));
	for (float r : ranges) out << (std::isfinite(r) ? mrpt::format(",%.4f", r) : std::string(",inf"));
	out << "\n";
}
}  // namespace

void GroundTruthWriter::add(
	const lvf::simulation::CStereoLaserSimulator::Frame& f)
{
	m_poses << mrpt::format(
		"%zu %.6f %.6f %.6f %.6f\n", f.index,
		mrpt::Clock::toDouble(f.timestamp), f.truePose.x(), f.truePose.y(),
		f.truePose.phi());

	writeScanRow(m_truth, f, f.truthScan);
	writeScanRow(m_seenTruth, f, f.seenTruthScan);

	if (m_writeDepth)
		lvf::common::writeImage(
			m_files.stage(mrpt::format("%s_depth/%06zu.pfm", m_name.c_str(), f.index)), f.leftDepth);
}

void GroundTruthWriter::writeObstacleMap(const lvf::simulation::World& world)
{
	const auto grid = lvf::simulation::obstacleGrid(world);
	lvf::common::saveGrid(grid, m_files.stage(m_name + "_obstacles.gridmap.gz"));
	const std::string picture = m_files.stage(m_name + "_obstacles.png");
	lvf::common::requireWritten(grid.saveAsBitmapFile(picture), picture);
}

void GroundTruthWriter::close()
{
	m_poses.close();
	m_truth.close();
	m_seenTruth.close();
}

}  // namespace lvf::apps
