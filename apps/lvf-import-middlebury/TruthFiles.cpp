#include "TruthFiles.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/WrittenFiles.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>

#include <cmath>
#include <fstream>

namespace lvf::apps
{
namespace
{
std::ofstream openForWriting(const std::string& path)
{
	std::ofstream out(path);
	if (!out) throw lvf::common::InputError(path, "", "cannot open for writing");
	return out;
}
}  // namespace

void writeGroundTruthPose(const std::string& path, mrpt::Clock::time_point stamp)
{
	auto out = openForWriting(path);
	out << "# ground-truth robot poses: frame timestamp[s] x[m] y[m] yaw[rad]\n";
	out << mrpt::format("%zu %.6f %.6f %.6f %.6f\n", size_t(0), mrpt::Clock::toDouble(stamp), 0.0, 0.0, 0.0);
	lvf::common::closeWritten(out, path);
}

void writeTruthScan(
	const std::string& path, const mrpt::obs::CObservation2DRangeScan& scan,
	const std::vector<float>& truth)
{
	auto out = openForWriting(path);
	out << "frame,timestamp";
	for (size_t i = 0; i < truth.size(); i++)
		out << mrpt::format(",b%.2f", mrpt::RAD2DEG(scan.getScanAngle(i)));
	out << "\n" << 0 << mrpt::format(",%.6f", mrpt::Clock::toDouble(scan.timestamp));
	for (float r : truth) out << (std::isfinite(r) ? mrpt::format(",%.4f", r) : std::string(",inf"));
	out << "\n";
	lvf::common::closeWritten(out, path);
}

}  // namespace lvf::apps
