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

	// Where the model sends each left pixel in the right image (same row).
	cv::Mat1f mapX(size), mapY(size);
	cv::Mat1b unverifiable(size);
	for (int v = 0; v < size.height; v++)
		for (int u = 0; u < size.width; u++)
		{
			const float d = modelDisparity(v, u);
			const float x = static_cast<float>(u - d + geometry.cxOffset);
			mapX(v, u) = x;
			mapY(v, u) = static_cast<float>(v);
			unverifiable(v, u) = (d <= 0 || x < 0 || x > size.width - 1) ? 255 : 0;
		}
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

	out.ncc.create(size);
	out.leftStd.create(size);
	out.state.create(size);
	const float minVar = static_cast<float>(m_options.minTextureStd * m_options.minTextureStd);
	const float threshold = static_cast<float>(m_options.nccThreshold);
	for (int v = 0; v < size.height; v++)
		for (int u = 0; u < size.width; u++)
		{
			const float mL = out.leftMean(v, u), mW = meanW(v, u);
			const float varL = std::max(0.f, meanLL(v, u) - mL * mL);
			const float varW = std::max(0.f, meanWW(v, u) - mW * mW);
			out.leftStd(v, u) = std::sqrt(varL);
			// A flat right window against a textured left one is a mismatch,
			// not a lack of evidence: its NCC is taken as 0.
			const float ncc = varW < minVar
				? 0.f
				: (meanLW(v, u) - mL * mW) / std::sqrt(varL * varW + 1e-6f);
			out.ncc(v, u) = ncc;
			PixelState s = PixelState::Consistent;
			if (unverifiable(v, u)) s = PixelState::Unverifiable;
			else if (varL < minVar) s = PixelState::Untextured;
			else if (ncc < threshold) s = PixelState::Inconsistent;
			out.state(v, u) = static_cast<uint8_t>(s);
			out.counts[static_cast<size_t>(s)]++;
		}
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
			else if (s != PixelState::Consistent) p = cv::Vec3b(96 + p[0] / 2, p[1] * 2 / 3, p[2] * 2 / 3);
		}
	return out;
}

}  // namespace lvf::evaluation
