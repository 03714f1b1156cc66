#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/depth/DisparityInterval.h>
#include <lvfusion/depth/FocusedEpipolarSearch.h>
#include <opencv2/imgproc.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace lvf::depth
{
using lvf::common::writeOption;
using lvf::evaluation::PixelState;

void FocusedEpipolarSearch::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	criterionA = ini.flag("criterion_a", criterionA);
	dAllow = ini.real("d_allow", dAllow, 0, 100);
	criterionB = ini.flag("criterion_b", criterionB);
	criterionC = ini.flag("criterion_c", criterionC);
	zMin = ini.real("z_min", zMin, 0.01, 1000);
	zMax = ini.real("z_max", zMax, zMin, 1000);
	boundByBand = ini.flag("bound_by_height_band", boundByBand);
	pixelStride = ini.integer("pixel_stride", pixelStride, 1, 32);
	acceptNcc = ini.real("accept_ncc", acceptNcc, -1, 1);
	uniquenessMargin = ini.real("uniqueness_margin", uniquenessMargin, 0, 2);
	peakContext = ini.integer("peak_context", peakContext, 1, 64);
	minTextureStd = ini.real("min_texture_std", minTextureStd, 0, 128);
	verifyFullLine = ini.flag("verify_full_line", verifyFullLine);
	ini.rejectUnknownKeys();
}

void FocusedEpipolarSearch::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "criterion_a", criterionA, "search only |Z - Z_laser| >= d_allow (paper Fig. 6a)");
	writeOption(c, s, "d_allow", dAllow, "criterion a's margin around the model depth [m]");
	writeOption(c, s, "criterion_b", criterionB, "search only Z <= Z_laser, in front of the model (Fig. 6b)");
	writeOption(c, s, "criterion_c", criterionC, "search only z_min <= Z <= z_max (Fig. 6c)");
	writeOption(c, s, "z_min", zMin, "nearest depth searched [m]");
	writeOption(c, s, "z_max", zMax, "farthest depth searched [m]");
	writeOption(c, s, "bound_by_height_band", boundByBand, "search only depths whose point lies in the robot height band");
	writeOption(c, s, "pixel_stride", pixelStride, "search every n-th inconsistent pixel along rows and columns");
	writeOption(c, s, "accept_ncc", acceptNcc, "a match must score at least this NCC [-1..1]");
	writeOption(c, s, "uniqueness_margin", uniquenessMargin, "any other NCC peak must be lower by this much");
	writeOption(c, s, "min_texture_std", minTextureStd, "search only windows with at least this std: matching needs more texture than checking [grey levels]");
	writeOption(c, s, "peak_context", peakContext, "NCC also scored this far outside the allowed range, so a peak cut by a bound is seen [px]");
	writeOption(c, s, "verify_full_line", verifyFullLine, "a match must also beat the whole epipolar line (not only the searched stretch)");
}

namespace
{
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/** Right-image columns to test for left pixel column u, from the disparity
 * set (d = u + cxOffset - column), clipped to where a window fits. */
struct ColumnRange
{
	int lo, hi;
};

}  // namespace

FocusedEpipolarSearch::Result FocusedEpipolarSearch::search(
	const cv::Mat1b& left, const cv::Mat1b& right,
	const lvf::evaluation::ModelEvaluation& evaluation, int windowSize,
	const lvf::evaluation::RectifiedGeometry& g, const HeightBand& band) const
{
	Result out;
	const int half = windowSize / 2;
	const int W = left.cols, H = left.rows;
	const cv::Size window(windowSize, windowSize);
	const float area = static_cast<float>(windowSize * windowSize);

	cv::Mat1f L, R, meanR, meanRR;
	left.convertTo(L, CV_32F);
	right.convertTo(R, CV_32F);
	cv::blur(R, meanR, window);
	cv::blur(R.mul(R), meanRR, window);

	const Eigen::Matrix3d Rc = g.leftPose.getRotationMatrix().asEigen();
	const Eigen::Vector3d C(g.leftPose.x(), g.leftPose.y(), g.leftPose.z());
	const double fB = g.fB();

	// NCC of the left window at (u, v) with the right window at (x, v).
	auto ncc = [&](int u, int v, int x, float meanL, float stdL) -> float {
		float sum = 0;
		for (int dy = -half; dy <= half; dy++)
		{
			const float* l = L.ptr<float>(v + dy) + u - half;
			const float* r = R.ptr<float>(v + dy) + x - half;
			for (int k = 0; k < windowSize; k++) sum += l[k] * r[k];
		}
		const float mR = meanR(v, x);
		const float varR = meanRR(v, x) - mR * mR;
		if (varR <= 1e-3f) return -1.f;
		return (sum / area - meanL * mR) / (stdL * std::sqrt(varR));
	};

	std::vector<float> scores;
	for (int v = half; v < H - half; v += m_options.pixelStride)
		for (int u = half; u < W - half; u += m_options.pixelStride)
		{
			if (evaluation.state(v, u) != static_cast<uint8_t>(PixelState::Inconsistent) ||
				evaluation.leftStd(v, u) < m_options.minTextureStd)
				continue;
			// Disparities whose right window lies inside the image.
			DisparitySet set({std::max(0.5, u + g.cxOffset - (W - 1 - half)), u + g.cxOffset - half});
			if (m_options.criterionC) set.intersect({fB / m_options.zMax, fB / m_options.zMin});
			const double dModel = evaluation.modelDisparity(v, u);
			if (dModel > 0)
			{
				const double zModel = fB / dModel;
				if (m_options.criterionB) set.intersect({dModel, kInfinity});
				if (m_options.criterionA)
					set.remove(
						fB / (zModel + m_options.dAllow),
						zModel > m_options.dAllow ? fB / (zModel - m_options.dAllow) : kInfinity);
			}
			const Eigen::Vector3d ray = Rc * Eigen::Vector3d(g.rayX(u), g.rayY(v), 1.0);
			if (m_options.boundByBand)
			{
				// Height along the ray: C.z + Z ray.z, for depth Z.
				if (std::abs(ray.z()) < 1e-12)
				{
					if (!band.contains(C.z())) set.intersect({1, 0});
				}
				else
				{
					const double z1 = (band.low - C.z()) / ray.z(), z2 = (band.high - C.z()) / ray.z();
					const double zNear = std::min(z1, z2), zFar = std::max(z1, z2);
					if (zFar <= 0) set.intersect({1, 0});
					else set.intersect({fB / zFar, zNear > 0 ? fB / zNear : kInfinity});
				}
			}
			if (set.empty() || set.integerCount() == 0)
			{
				out.stats.skippedEmptyRange++;
				continue;
			}
			out.stats.searchedPixels++;

			const float meanL = evaluation.leftMean(v, u), stdL = evaluation.leftStd(v, u);
			// Score every right column in the allowed set (column x holds
			// disparity u + cxOffset - x: columns decrease as d grows).
			int bestX = -1;
			float best = -2.f;
			scores.assign(static_cast<size_t>(W), std::numeric_limits<float>::quiet_NaN());
			const int context = m_options.peakContext;
			for (size_t k = 0; k < set.size(); k++)
			{
				const int xLo = static_cast<int>(std::ceil(u + g.cxOffset - set[k].hi));
				const int xHi = static_cast<int>(std::floor(u + g.cxOffset - set[k].lo));
				for (int x = std::max(xLo - context, half); x <= std::min(xHi + context, W - 1 - half); x++)
				{
					if (std::isnan(scores[x]))
					{
						scores[x] = ncc(u, v, x, meanL, stdL);
						out.stats.disparitiesTested++;
					}
					if (x >= xLo && x <= xHi && scores[x] > best) best = scores[x], bestX = x;
				}
			}
			if (bestX < 0) continue;
			if (best < m_options.acceptNcc)
			{
				out.stats.rejectedWeak++;
				continue;
			}
			// A true peak: both neighbours lower, scored even if outside the set.
			auto scoreAt = [&](int x) {
				if (x < half || x > W - 1 - half) return -2.f;
				if (std::isnan(scores[x])) scores[x] = ncc(u, v, x, meanL, stdL);
				return scores[x];
			};
			const float before = scoreAt(bestX - 1), after = scoreAt(bestX + 1);
			if (before >= best || after >= best)
			{
				out.stats.rejectedNotPeak++;
				continue;
			}
			// Unique: no other local maximum close to it.
			bool ambiguous = false;
			for (int x = half + 1; x < W - 1 - half && !ambiguous; x++)
				if (std::abs(x - bestX) > 1 && !std::isnan(scores[x]) &&
					scores[x] > best - m_options.uniquenessMargin &&
					!(scores[x - 1] > scores[x]) && !(scores[x + 1] > scores[x]))
					ambiguous = true;
			if (ambiguous)
			{
				out.stats.rejectedAmbiguous++;
				continue;
			}
			// The laser's model must explain the pixel clearly worse: if the
			// right image matches about as well at the model's own disparity
			// (best of a few columns, for its sub-pixel error), the evidence
			// does not favour an obstacle.
			if (dModel > 0)
			{
				const int xModel = static_cast<int>(std::lround(u + g.cxOffset - dModel));
				float modelScore = -2.f;
				for (int x = xModel - 2; x <= xModel + 2; x++) modelScore = std::max(modelScore, scoreAt(x));
				if (modelScore > best - m_options.uniquenessMargin)
				{
					out.stats.rejectedAmbiguous++;
					continue;
				}
			}
			// Where the criteria cut the true match away (it lies behind the
			// model, or farther than z_max), a side lobe can win inside the
			// set. So a candidate must also beat every other peak of the
			// epipolar line, from twice z_max to z_min (its own peak's
			// shoulders, which descend from it, do not count).
			if (m_options.verifyFullLine)
			{
				const int xFar = std::min(W - 1 - half, static_cast<int>(std::floor(u + g.cxOffset - fB / (2 * m_options.zMax))));
				const int xNear = std::max(half, static_cast<int>(std::ceil(u + g.cxOffset - fB / m_options.zMin)));
				int peakLo = bestX, peakHi = bestX;
				while (peakLo - 1 >= xNear && scoreAt(peakLo - 1) < scoreAt(peakLo)) peakLo--;
				while (peakHi + 1 <= xFar && scoreAt(peakHi + 1) < scoreAt(peakHi)) peakHi++;
				bool beaten = false;
				for (int x = xNear; x <= xFar && !beaten; x++)
					if (x < peakLo || x > peakHi) beaten = scoreAt(x) > best - m_options.uniquenessMargin;
				if (beaten)
				{
					out.stats.rejectedAmbiguous++;
					continue;
				}
			}
			// Parabola through the peak and its neighbours.
			const float curvature = before - 2 * best + after;
			const float shift = curvature < 0 ? 0.5f * (before - after) / curvature : 0.f;
			const double disparity = u + g.cxOffset - (bestX + shift);
			if (disparity <= 0) continue;
			const double Z = fB / disparity;
			const Eigen::Vector3d p = C + Z * ray;
			if (!band.contains(p.z()))
			{
				out.stats.rejectedOutOfBand++;
				continue;
			}
			out.points.push_back({static_cast<float>(u), static_cast<float>(v),
								  static_cast<float>(disparity), best, p});
			out.stats.accepted++;
		}
	return out;
}

}  // namespace lvf::depth
