#pragma once
// The model check's NCC at the pixels of one grid row, from their exact
// window sums (GridWindowSums), a row at a time: the per-pixel formula it
// replaced, bit for bit, with its divisions and square roots over whole
// arrays, where they run vectorised (pixel by pixel they took most of the
// grid check's arithmetic). Against ModelEvaluator::evaluate(), whose float
// box filters round differently, it agrees to rounding (test_model_evaluation,
// GridEvaluationJudgesItsPixelsLikeTheWholeImage).

#include <lvfusion/evaluation/GridWindowSums.h>

#include <vector>

namespace lvf::evaluation
{
class GridRowNcc
{
   public:
	/** Windows of `area` pixels; a warped window whose variance is below
	 * `minVariance` scores NCC 0 (a flat right window against a textured
	 * left one is a mismatch, not a lack of evidence). */
	GridRowNcc(double area, double minVariance) : m_area(area), m_minVariance(minVariance) {}

	/** The values at columns first, first + stride, ... (count of them) of
	 * the row `sums` stands at; read them with the accessors below, by the
	 * column's index i. */
	void compute(const GridWindowSums& sums, int first, int stride, int count);

	double leftMean(int i) const { return m_leftMean[size_t(i)]; }
	double leftVariance(int i) const { return m_leftVariance[size_t(i)]; }
	double leftStd(int i) const { return m_leftStd[size_t(i)]; }
	double ncc(int i) const { return m_ncc[size_t(i)]; }
	/** Pixels of the window without a match (GridWindowSums::Sums). */
	int64_t unverifiable(int i) const { return m_unverifiable[size_t(i)]; }

   private:
	const double m_area, m_minVariance;
	std::vector<double> m_l, m_ll, m_w32, m_ww1024, m_lw32;
	std::vector<int64_t> m_unverifiable;
	std::vector<double> m_leftMean, m_leftVariance, m_warpedVariance, m_covariance, m_denominator, m_leftStd, m_ncc;
};

}  // namespace lvf::evaluation
