#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RowBands.h>
#include <lvfusion/evaluation/GridRowNcc.h>
#include <lvfusion/evaluation/GridWindowSums.h>
#include <lvfusion/evaluation/ImageNoise.h>
#include <lvfusion/evaluation/ModelEvaluator.h>
#include <lvfusion/evaluation/ModelWarp.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace lvf::evaluation
{
using lvf::common::writeOption;

void ModelEvaluator::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	windowSize = ini.integer("window_size", windowSize, 3, 31);
	if (windowSize % 2 == 0)
		throw lvf::common::InputError(
			ini.sourceName(), "[" + section + "] window_size", "must be odd");
	nccThreshold = ini.real("ncc_threshold", nccThreshold, -1, 1);
	textureNoiseRatio = ini.real("texture_noise_ratio", textureNoiseRatio, 0, 100);
	minTextureStd = ini.real("min_texture_std", minTextureStd, 0, 128);
	ini.rejectUnknownKeys();
}

void ModelEvaluator::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "window_size", windowSize, "NCC window side of the model check and of the depth search's matching, odd [px]");
	writeOption(c, s, "ncc_threshold", nccThreshold, "NCC below this: the model is wrong there [-1..1]");
	writeOption(c, s, "texture_noise_ratio", textureNoiseRatio, "window std below this many times the image's noise (estimated per frame): untextured, not judged");
	writeOption(c, s, "min_texture_std", minTextureStd, "or below this, whatever the noise [grey levels]");
}

namespace
{
/** The image noise the texture gates are set from: the cameras' as taken
 * where rectification resampled the pair, else estimated on `left`. */
double noiseStdOf(const cv::Mat1b& left, const RectificationEffects& rectification)
{
	return rectification.sensorNoiseStd ? *rectification.sensorNoiseStd : estimateNoiseStd(left);
}

/** The right image warped by the model (warpByModel), and every pixel it
 * cannot be judged at: those the warp marks, and those rectification
 * filled from outside the left image. */
void warpForJudging(const cv::Mat1b& right, const cv::Mat1f& modelDisparity, const RectifiedGeometry& geometry,
	const RectificationEffects& rectification, cv::Mat1w& warped32, cv::Mat1b& unverifiable)
{
	warpByModel(right, modelDisparity, geometry, warped32, unverifiable, rectification.rightNotImaged);
	if (!rectification.leftNotImaged.empty()) unverifiable.setTo(255, rectification.leftNotImaged);
}
}  // namespace

ModelEvaluation ModelEvaluator::evaluate(
	const cv::Mat1b& left, const cv::Mat1b& right,
	const cv::Mat1f& modelDisparity, const RectifiedGeometry& geometry,
	const RectificationEffects& rectification) const
{
	ModelEvaluation out;
	out.modelDisparity = modelDisparity;
	out.noiseStd = noiseStdOf(left, rectification);
	out.textureGate = m_options.textureGate(out.noiseStd);
	const cv::Size size = left.size();
	const cv::Size window(m_options.windowSize, m_options.windowSize);

	cv::Mat1w warped32;
	cv::Mat1b unverifiable;
	warpForJudging(right, modelDisparity, geometry, rectification, warped32, unverifiable);
	cv::Mat1f warped;
	warped32.convertTo(warped, CV_32F, 1.0 / 32);  // exact: a power of two
	// A window touching an unverifiable pixel mixes in meaningless values.
	cv::dilate(unverifiable, unverifiable, cv::Mat::ones(window, CV_8U));

	cv::Mat1f L;
	left.convertTo(L, CV_32F);
	cv::Mat1f meanW, meanLL, meanWW, meanLW;
	cv::blur(L, out.gridLeftMean, window);
	cv::blur(warped, meanW, window);
	cv::blur(L.mul(L), meanLL, window);
	cv::blur(warped.mul(warped), meanWW, window);
	cv::blur(L.mul(warped), meanLW, window);

	const cv::Mat1f varL = cv::max(meanLL - out.gridLeftMean.mul(out.gridLeftMean), 0.0);
	const cv::Mat1f varW = cv::max(meanWW - meanW.mul(meanW), 0.0);
	cv::sqrt(varL, out.gridLeftStd);
	cv::Mat1f denominator;
	cv::sqrt(varL.mul(varW) + 1e-6, denominator);
	cv::divide(meanLW - out.gridLeftMean.mul(meanW), denominator, out.gridNcc);
	const double minVar = out.textureGate * out.textureGate;
	// A flat right window against a textured left one is a mismatch, not a
	// lack of evidence: its NCC is taken as 0.
	out.gridNcc.setTo(0, varW < minVar);

	// States, the later rules overriding the earlier ones.
	out.state = cv::Mat1b(size, static_cast<uint8_t>(PixelState::Consistent));
	out.state.setTo(static_cast<uint8_t>(PixelState::Inconsistent), out.gridNcc < m_options.nccThreshold);
	out.state.setTo(static_cast<uint8_t>(PixelState::Untextured), varL < minVar);
	out.state.setTo(static_cast<uint8_t>(PixelState::Unverifiable), unverifiable);
	out.state.setTo(static_cast<uint8_t>(PixelState::Unmodelled), (modelDisparity <= 0) & (varL >= minVar));
	for (size_t k = 0; k < out.counts.size(); k++)
		out.counts[k] = static_cast<size_t>(cv::countNonZero(out.state == static_cast<uint8_t>(k)));
	return out;
}

ModelEvaluation ModelEvaluator::evaluateGrid(
	const cv::Mat1b& left, const cv::Mat1b& right, const cv::Mat1f& modelDisparity,
	const RectifiedGeometry& geometry, int first, int stride, const RectificationEffects& rectification) const
{
	const int half = m_options.windowSize / 2;
	if (first < half || stride < 1)
		throw std::invalid_argument("evaluateGrid: the grid must start at window_size / 2 or later");
	ModelEvaluation out;
	out.modelDisparity = modelDisparity;
	out.noiseStd = noiseStdOf(left, rectification);
	out.textureGate = m_options.textureGate(out.noiseStd);
	const cv::Size size = left.size();
	cv::Mat1w warped32;
	cv::Mat1b unverifiable;
	warpForJudging(right, modelDisparity, geometry, rectification, warped32, unverifiable);

	// The grid's rows and columns where a window fits; every one is
	// written below.
	const int gridRows = std::max(0, (size.height - half - first + stride - 1) / stride);
	const int columns = std::max(0, (size.width - half - first + stride - 1) / stride);
	out.grid = PixelGrid{first, stride};
	out.gridNcc.create(gridRows, columns);
	out.gridLeftMean.create(gridRows, columns);
	out.gridLeftStd.create(gridRows, columns);
	out.state = cv::Mat1b(size, static_cast<uint8_t>(PixelState::NotEvaluated));
	const double area = double(m_options.windowSize * m_options.windowSize);
	const double minVar = out.textureGate * out.textureGate;
	// Bands of grid rows on OpenCV's threads, each with window sums of its
	// own (exact integers: the same values whichever row they start from).
	// Few bands: each starts its sums over a whole window of rows, where
	// moving down a grid row adds and drops only 2 x stride of them.
	const lvf::common::RowBands bands(first, size.height - half, stride, 4);
	std::vector<decltype(out.counts)> bandCounts(static_cast<size_t>(bands.count()), decltype(out.counts){});
	bands.forEach([&](int b, int firstRow, int endRow) {
		// Window sums on the grid's rows only, exact integers (GridWindowSums.h).
		GridWindowSums sums(left, warped32, unverifiable, half);
		GridRowNcc row(area, minVar);
		auto& counts = bandCounts[static_cast<size_t>(b)];
		for (int v = firstRow; v < endRow; v += stride)
		{
			sums.moveTo(v);
			row.compute(sums, first, stride, columns);
			const int j = out.grid.index(v);
			for (int i = 0, u = first; i < columns; i++, u += stride)
			{
				// The same rules, in the same order, as evaluate().
				const double ncc = row.ncc(i), varL = row.leftVariance(i);
				out.gridLeftMean(j, i) = static_cast<float>(row.leftMean(i));
				out.gridLeftStd(j, i) = static_cast<float>(row.leftStd(i));
				out.gridNcc(j, i) = static_cast<float>(ncc);
				PixelState s = ncc < m_options.nccThreshold ? PixelState::Inconsistent : PixelState::Consistent;
				if (varL < minVar) s = PixelState::Untextured;
				if (row.unverifiable(i) > 0) s = PixelState::Unverifiable;
				if (modelDisparity(v, u) <= 0 && varL >= minVar) s = PixelState::Unmodelled;
				out.state(v, u) = static_cast<uint8_t>(s);
				counts[static_cast<size_t>(s)]++;
			}
		}
	});
	for (const auto& counts : bandCounts)
		for (size_t k = 0; k < counts.size(); k++) out.counts[k] += counts[k];
	out.counts[static_cast<size_t>(PixelState::NotEvaluated)] =
		size.area() - std::accumulate(out.counts.begin(), out.counts.end(), size_t{0});
	return out;
}

cv::Mat3b drawEvaluationOverlay(const cv::Mat1b& left, const ModelEvaluation& e)
{
	cv::Mat3b out;
	cv::cvtColor(left, out, cv::COLOR_GRAY2BGR);
	for (int v = 0; v < out.rows; v++)
		for (int u = 0; u < out.cols; u++)
		{
			const auto s = static_cast<PixelState>(e.state(v, u));
			cv::Vec3b& p = out(v, u);
			if (s == PixelState::Inconsistent) p = cv::Vec3b(p[0] / 3, p[1] / 3, 128 + p[2] / 2);
			else if (s == PixelState::Unmodelled) p = cv::Vec3b(128 + p[0] / 2, p[1] / 3, 128 + p[2] / 2);
			else if (s != PixelState::Consistent && s != PixelState::NotEvaluated) p = cv::Vec3b(96 + p[0] / 2, p[1] * 2 / 3, p[2] * 2 / 3);
		}
	return out;
}

}  // namespace lvf::evaluation
