#include <lvfusion/lines/LineFit.h>

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace lvf::lines
{
LineFit fitLine(const PointMoments& m)
{
	LineFit fit;
	fit.n = m.n;
	if (m.n == 0) return fit;
	const double inv = 1.0 / static_cast<double>(m.n);
	fit.centroid = Eigen::Vector2d(m.sx * inv, m.sy * inv);
	if (m.n < 2)
	{
		fit.offset = fit.normal.dot(fit.centroid);
		return fit;
	}
	Eigen::Matrix2d cov;
	cov(0, 0) = m.sxx * inv - fit.centroid.x() * fit.centroid.x();
	cov(0, 1) = cov(1, 0) = m.sxy * inv - fit.centroid.x() * fit.centroid.y();
	cov(1, 1) = m.syy * inv - fit.centroid.y() * fit.centroid.y();
	// The line through the centroid along the major axis minimises the sum
	// of squared orthogonal distances; that sum / n is the minor eigenvalue.
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
	fit.normal = eig.eigenvectors().col(0).normalized();  // ascending order
	fit.offset = fit.normal.dot(fit.centroid);
	// Cancellation in sxx/n - mean^2 can leave a tiny negative value.
	fit.rmsResidual = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
	return fit;
}

}  // namespace lvf::lines
