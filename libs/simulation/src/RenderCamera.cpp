// SimulatedStereoRig::renderCamera: the per-pixel ray caster.
// Per frame, each box is projected to a bounding rectangle in normalised image
// coordinates; per tile of samples only the boxes whose rectangle overlaps the
// tile's rays are tested. That keeps a 640x480 pair of a furnished room at a
// few boxes per ray (see lvf-bench, RenderStereoPair vs. BruteForce).

#include <lvfusion/simulation/SimulatedStereoRig.h>

#include <algorithm>
#include <cmath>

namespace lvf::simulation
{
namespace
{
struct ScreenBounds
{
	bool visible = false;  //!< some corner in front of the camera
	bool everywhere = false;  //!< straddles the camera plane: no bound known
	float xMin = 0, xMax = 0, yMin = 0, yMax = 0;
};

/** Bounding rectangle of a box's projection, in normalised coordinates. A
 * convex solid projects into the convex hull of its projected corners, so the
 * rectangle around those corners contains every pixel that can see it. */
ScreenBounds projectBox(const Box& b, const mrpt::poses::CPose3D& camera)
{
	constexpr double kNear = 1e-3;
	ScreenBounds sb;
	sb.xMin = sb.yMin = 1e30f;
	sb.xMax = sb.yMax = -1e30f;
	const double c = std::cos(b.yaw), s = std::sin(b.yaw);
	int inFront = 0, behind = 0;
	for (int k = 0; k < 8; k++)
	{
		const double lx = ((k & 1) ? 0.5 : -0.5) * b.sizeX;
		const double ly = ((k & 2) ? 0.5 : -0.5) * b.sizeY;
		const double z = (k & 4) ? b.zMax() : b.zMin();
		double px, py, pz;
		camera.inverseComposePoint(
			b.x + c * lx - s * ly, b.y + s * lx + c * ly, z, px, py, pz);
		if (pz <= kNear)
		{
			behind++;
			continue;
		}
		inFront++;
		sb.xMin = std::min(sb.xMin, static_cast<float>(px / pz));
		sb.xMax = std::max(sb.xMax, static_cast<float>(px / pz));
		sb.yMin = std::min(sb.yMin, static_cast<float>(py / pz));
		sb.yMax = std::max(sb.yMax, static_cast<float>(py / pz));
	}
	sb.visible = inFront > 0;
	sb.everywhere = inFront > 0 && behind > 0;
	return sb;
}

}  // namespace

void SimulatedStereoRig::renderCamera(
	const WorldGeometry& world, const mrpt::poses::CPose3D& cameraPose,
	const CameraRayTable& rays, double gain, double noiseStd,
	uint64_t noiseSeed, cv::Mat1b& image, cv::Mat1f* depth,
	bool bruteForce) const
{
	const World& w = world.world();
	const int s = rays.supersampling();
	const int cols = rays.sampleCols() / s, rows = rays.sampleRows() / s;
	cv::Mat1f radiance = cv::Mat1f::zeros(rows, cols);
	if (depth)
		depth->create(rows, cols),
			depth->setTo(std::numeric_limits<float>::infinity());

	const Eigen::Matrix3d R = cameraPose.getRotationMatrix().asEigen();
	const Eigen::Vector3d origin(cameraPose.x(), cameraPose.y(), cameraPose.z());
	const Eigen::Vector3d toLight =
		Eigen::Vector3d(w.light.dirX, w.light.dirY, w.light.dirZ).normalized();

	std::vector<ScreenBounds> bounds(w.boxes.size());
	for (size_t i = 0; i < w.boxes.size(); i++)
		bounds[i] = projectBox(w.boxes[i], cameraPose);

	std::vector<int> candidates;
	candidates.reserve(w.boxes.size());
	const float sampleWeight = 1.0f / static_cast<float>(s * s);
	const double sampleAngle = 1.0 / (m_options.fx * s);  // [rad] near the axis
	const int centreSample = s / 2;
	for (const auto& tile : rays.tiles())
	{
		candidates.clear();
		for (size_t i = 0; i < bounds.size(); i++)
		{
			const ScreenBounds& b = bounds[i];
			const bool overlaps = b.everywhere ||
				(b.visible && b.xMax >= tile.xMin && b.xMin <= tile.xMax &&
				 b.yMax >= tile.yMin && b.yMin <= tile.yMax);
			if (overlaps || bruteForce) candidates.push_back(static_cast<int>(i));
		}
		for (int r = tile.row0; r < tile.row1; r++)
			for (int c = tile.col0; c < tile.col1; c++)
			{
				// Ray (x, y, 1) in the camera: its parameter t is the depth z.
				const Eigen::Vector3d dir =
					R * Eigen::Vector3d(rays.rayX(c, r), rays.rayY(c, r), 1.0);
				const RayHit hit = world.castRay(
					origin, dir, candidates.data(), candidates.size());
				float shade = static_cast<float>(w.light.background);
				if (hit.hit())
				{
					const Eigen::Vector3d normal = world.normalAt(hit);
					const double lambert = std::max(0.0, normal.dot(toLight));
					// The sample's size on the surface: distance times its
					// angular size, stretched by the viewing obliquity.
					const double length = dir.norm();
					const double obliquity = std::max(0.2, std::abs(normal.dot(dir)) / length);
					const double footprint = hit.t * length * sampleAngle / obliquity;
					shade = world.albedoAt(hit, origin, dir, footprint) *
						static_cast<float>(w.light.ambient + w.light.diffuse * lambert);
				}
				radiance(r / s, c / s) += sampleWeight * shade;
				if (depth && r % s == centreSample && c % s == centreSample)
					(*depth)(r / s, c / s) = static_cast<float>(hit.t);
			}
	}

	cv::Mat1f noise(rows, cols);
	cv::RNG rng(noiseSeed ^ 0x9e3779b97f4a7c15ULL);
	rng.fill(noise, cv::RNG::NORMAL, 0.0, noiseStd);
	cv::Mat1f grey = radiance * (255.0 * gain) + noise;
	grey.convertTo(image, CV_8U);  // rounds and saturates to [0, 255]
}

}  // namespace lvf::simulation
