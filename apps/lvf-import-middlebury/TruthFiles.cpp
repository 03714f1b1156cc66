#include "TruthFiles.h"

#include <lvfusion/common/WrittenFiles.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>

#include <cmath>

namespace lvf::apps
{
void writeGroundTruthPose(const std::string& path, mrpt::Clock::time_point stamp)
{
	lvf::common::OutputFile out(path);
	out << "# ground-truth robot poses: frame timestamp[s] x[m] y[m] yaw[rad]\n";
	out << mrpt::format("%zu %.6f %.6f %.6f %.6f\n", size_t(0), mrpt::Clock::toDouble(stamp), 0.0, 0.0, 0.0);
	out.close();
}

void writeTruthScan(
	const std::string& path, const mrpt::obs::CObservation2DRangeScan& scan,
	const std::vector<float>& truth)
{
	lvf::common::OutputFile out(path);
	out << "frame,timestamp";
	for (size_t i = 0; i < truth.size(); i++)
		out << mrpt::format(",b%.2f", mrpt::RAD2DEG(scan.getScanAngle(i)));
	out << "\n" << 0 << mrpt::format(",%.6f", mrpt::Clock::toDouble(scan.timestamp));
	for (float r : truth) out << (std::isfinite(r) ? mrpt::format(",%.4f", r) : std::string(",inf"));
	out << "\n";
	out.close();
}

}  // namespace lvf::apps
