#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/depth/FocusedEpipolarSearch.h>

// [FocusedEpipolarSearch]: reading the options, and writing them with their
// units and meaning (fusion.ini is this function's output).

namespace lvf::depth
{
using lvf::common::writeOption;

void FocusedEpipolarSearch::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	criterionA = ini.flag("criterion_a", criterionA);
	dAllow = ini.real("d_allow", dAllow, 0, 100);
	floorDisparityMargin = ini.real("floor_disparity_margin", floorDisparityMargin, 0, 1000);
	criterionB = ini.flag("criterion_b", criterionB);
	criterionC = ini.flag("criterion_c", criterionC);
	zMin = ini.real("z_min", zMin, 0.01, 1000);
	zMax = ini.real("z_max", zMax, zMin, 1000);
	boundByBand = ini.flag("bound_by_height_band", boundByBand);
	pixelStride = ini.integer("pixel_stride", pixelStride, 1, 32);
	nearestFirstLevels = ini.integer("nearest_first_levels", nearestFirstLevels, 0, 4);
	nearestFirstPoints = ini.integer("nearest_first_points", nearestFirstPoints, 1, 1000);
	acceptNcc = ini.real("accept_ncc", acceptNcc, -1, 1);
	uniquenessMargin = ini.real("uniqueness_margin", uniquenessMargin, 0, 2);
	peakContext = ini.integer("peak_context", peakContext, 1, 64);
	textureNoiseRatio = ini.real("texture_noise_ratio", textureNoiseRatio, 0, 100);
	minTextureStd = ini.real("min_texture_std", minTextureStd, 0, 128);
	verifyFullLine = ini.flag("verify_full_line", verifyFullLine);
	leftRightCheck = ini.flag("left_right_check", leftRightCheck);
	coarseToFine = ini.flag("coarse_to_fine", coarseToFine);
	coreWindow = ini.integer("core_window", coreWindow, 0, 31);
	if (coreWindow % 2 == 0 && coreWindow != 0)
		throw lvf::common::InputError(
			ini.sourceName(), "[" + section + "] core_window", "must be odd, or 0 for off");
	coreAcceptNcc = ini.real("core_accept_ncc", coreAcceptNcc, -1, 1);
	shiftedWindows = ini.flag("shifted_windows", shiftedWindows);
	subpixelIterations = ini.integer("subpixel_iterations", subpixelIterations, 0, 20);
	subpixelSigma = ini.real("subpixel_sigma", subpixelSigma, 0.5, 100);
	ini.rejectUnknownKeys();
}

void FocusedEpipolarSearch::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "criterion_a", criterionA, "search only |Z - Z_laser| >= d_allow (paper Fig. 6a)");
	writeOption(c, s, "d_allow", dAllow, "criterion a's margin around the model depth [m]");
	writeOption(c, s, "floor_disparity_margin", floorDisparityMargin, "where the model is the floor, criterion a's margin in front of it at most this much disparity, the band's lower edge deciding the rest (with bound_by_height_band; finds obstacles a few cm tall on rigs that resolve them); 0: off, d_allow as on walls [px]");
	writeOption(c, s, "criterion_b", criterionB, "search only Z <= Z_laser, in front of the model (Fig. 6b)");
	writeOption(c, s, "criterion_c", criterionC, "search only z_min <= Z <= z_max (Fig. 6c)");
	writeOption(c, s, "z_min", zMin, "nearest depth searched [m]; the search's work grows with f * baseline / z_min, the disparity it reaches (0.3 m: 180 px on the simulated rig, 640 on Middlebury Motorcycle's)");
	writeOption(c, s, "z_max", zMax, "farthest depth searched [m]");
	writeOption(c, s, "bound_by_height_band", boundByBand, "search only depths whose point lies in the robot height band");
	writeOption(c, s, "pixel_stride", pixelStride, "search the inconsistent and unmodelled pixels of a grid of this step along rows and columns");
	writeOption(c, s, "nearest_first_levels", nearestFirstLevels, "search every 2^L-th grid row first, then the rows halfway between, and so on; a later pass searches a pixel only in front of what earlier passes found on its bearing (the fused scan keeps a bearing's nearest obstacle); 0: every grid row in one pass");
	writeOption(c, s, "nearest_first_points", nearestFirstPoints, "the points earlier passes must have found on a bearing before it is bounded, at the nearest_first_points-th nearest of them");
	writeOption(c, s, "accept_ncc", acceptNcc, "a match must score at least this NCC [-1..1]");
	writeOption(c, s, "uniqueness_margin", uniquenessMargin, "any other NCC peak must be lower by this much");
	writeOption(c, s, "texture_noise_ratio", textureNoiseRatio, "search only windows whose std is at least this many times the image's noise: matching needs more texture than checking");
	writeOption(c, s, "min_texture_std", minTextureStd, "and at least this, whatever the noise [grey levels]");
	writeOption(c, s, "peak_context", peakContext, "NCC also scored this far outside the allowed range, so a peak cut by a bound is seen [px]");
	writeOption(c, s, "verify_full_line", verifyFullLine, "a match must also beat the whole epipolar line (not only the searched stretch)");
	writeOption(c, s, "core_window", coreWindow, "a match must also hold on this smaller centred window, better than at the model's disparity, so a window just beside an object does not take the object's depth; 0: off [px, odd]");
	writeOption(c, s, "core_accept_ncc", coreAcceptNcc, "NCC the core window must reach at the match [-1..1]");
	writeOption(c, s, "shifted_windows", shiftedWindows, "a match must not be explained better by the model on a window shifted sideways until the pixel lies on its edge (the background beside an object's silhouette): a third fewer phantom bearings, a few obstacle edges lost (README)");
	writeOption(c, s, "subpixel_iterations", subpixelIterations, "Lucas-Kanade steps along the row after the parabola, on a window weighted round its centre, so the centre pixel's surface decides the sub-pixel disparity (2: fewer phantoms, more recall, README); 0: the parabola alone");
	writeOption(c, s, "subpixel_sigma", subpixelSigma, "those weights' Gaussian standard deviation [px]");
	writeOption(c, s, "coarse_to_fine", coarseToFine, "find and verify matches on the half-resolution pair, refine them on the full one (~8x fewer products)");
	writeOption(c, s, "left_right_check", leftRightCheck, "the matched right window, searched back along the left row, must find the left pixel again");
}

}  // namespace lvf::depth
