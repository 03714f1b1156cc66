#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/evaluation/ModelEvaluator.h>
#include <opencv2/imgproc.hpp>

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
	minTextureStd = ini.real("min_texture_std", minTextureStd, 0, 128);
	ini.rejectUnknownKeys();
}

void ModelEvaluator::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "window_size", windowSize, "NCC window side, odd [px]");
	writeOption(c, s, "ncc_threshold", nccThreshold, "NCC below this: the model is wrong there [-1..1]");
	writeOption(c, s, "min_texture_std", minTextureStd, "window std below this: untextured, not judged [grey levels]");
}

ModelEvaluation ModelEvaluator::evaluate(
	const cv::Mat1b& left, const cv::Mat1b& right,
	const cv::Mat1f& modelDisparity, const RectifiedGeometry& geometry) const
{
	ModelEvaluation out;
	out.modelDisparity = modelDisparity;
	const cv::Size size = left.size();
	const cv::Size window(m_options.windowSize, m_options.windowSize);

	// Where the model sends each left pixel in the right image (same row),
	// whole-image operations throughout (OpenCV vectorises them).
	cv::Mat1f columns(1, size.width), rows(size.height, 1);
	for (int u = 0; u < size.width; u++) columns(0, u) = static_cast<float>(u);
	for (int v = 0; v < size.height; v++) rows(v, 0) = static_cast<float>(v);
	cv::Mat1f mapX, mapY;
	cv::repeat(columns, size.height, 1, mapX);
	cv::repeat(rows, 1, size.width, mapY);
	mapX = mapX - modelDisparity + static_cast<float>(geometry.cxOffset);
	const cv::Mat1b unmodelled = modelDisparity <= 0;
	cv::Mat1b unverifiable = unmodelled | (mapX < 0) | (mapX > size.width - 1);
	cv::Mat1f rightF, warped;
	right.convertTo(rightF, CV_32F);  // interpolate without rounding to 8 bits
	cv::remap(rightF, warped, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
	// A window touching an unverifiable pixel mixes in meaningless values.
	cv::dilate(unverifiable, unverifiable, cv::Mat::ones(window, CV_8U));

	cv::Mat1f L;
	left.convertTo(L, CV_32F);
	cv::Mat1f meanW, meanLL, meanWW, meanLW;
	cv::blur(L, out.leftMean, window);
	cv::blur(warped, meanW, window);
	cv::blur(L.mul(L), meanLL, window);
	cv::blur(warped.mul(warped), meanWW, window);
	cv::blur(L.mul(warped), meanLW, window);

	const cv::Mat1f varL = cv::max(meanLL - out.leftMean.mul(out.leftMean), 0.0);
	const cv::Mat1f varW = cv::max(meanWW - meanW.mul(meanW), 0.0);
	cv::sqrt(varL, out.leftStd);
	cv::Mat1f denominator;
	cv::sqrt(varL.mul(varW) + 1e-6, denominator);
	cv::divide(meanLW - out.leftMean.mul(meanW), denominator, out.ncc);
	const double minVar = m_options.minTextureStd * m_options.minTextureStd;
	// A flat right window against a textured left one is a mismatch, not a
	// lack of evidence: its NCC is taken as 0.
	out.ncc.setTo(0, varW < minVar);

	// States, the later rules overriding the earlier ones.
	out.state = cv::Mat1b(size, static_cast<uint8_t>(PixelState::Consistent));
	out.state.setTo(static_cast<uint8_t>(PixelState::Inconsistent), out.ncc < m_options.nccThreshold);
	out.state.setTo(static_cast<uint8_t>(PixelState::Untextured), varL < minVar);
	out.state.setTo(static_cast<uint8_t>(PixelState::Unverifiable), unverifiable);
	out.state.setTo(static_cast<uint8_t>(PixelState::Unmodelled), unmodelled & (varL >= minVar));
	for (size_t k = 0; k < out.counts.size(); k++)
		out.counts[k] = static_cast<size_t>(cv::countNonZero(out.state == static_cast<uint8_t>(k)));
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
			else if (s != PixelState::Consistent) p = cv::Vec3b(96 + p[0] / 2, p[1] * 2 / 3, p[2] * 2 / 3);
		}
	return out;
}

}  // namespace lvf::evaluation
