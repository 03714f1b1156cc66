#pragma once
// Total least squares (orthogonal regression) line fit, from running sums of
// the points so that the fit of the union of two point sets costs O(1): the
// merge pass of ScanLineExtractor tries many unions.

#include <Eigen/Core>

#include <cmath>
#include <cstddef>

namespace lvf::lines
{
/** Sums of a 2D point set, taken relative to a reference point (the sensor)
 * so that the second moments do not lose their digits to large coordinates. */
struct PointMoments
{
	size_t n = 0;
	double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;

	void add(const Eigen::Vector2d& p)
	{
		n++;
		sx += p.x();
		sy += p.y();
		sxx += p.x() * p.x();
		sxy += p.x() * p.y();
		syy += p.y() * p.y();
	}
	PointMoments& operator+=(const PointMoments& o)
	{
		n += o.n;
		sx += o.sx;
		sy += o.sy;
		sxx += o.sxx;
		sxy += o.sxy;
		syy += o.syy;
		return *this;
	}
	/** Removes a subset that was added before. */
	PointMoments& operator-=(const PointMoments& o)
	{
		n -= o.n;
		sx -= o.sx;
		sy -= o.sy;
		sxx -= o.sxx;
		sxy -= o.sxy;
		syy -= o.syy;
		return *this;
	}
	friend PointMoments operator+(PointMoments a, const PointMoments& b)
	{
		return a += b;
	}
	friend PointMoments operator-(PointMoments a, const PointMoments& b)
	{
		return a -= b;
	}
};

struct LineFit
{
	Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
	Eigen::Vector2d normal = Eigen::Vector2d::UnitX();	//!< unit, sign arbitrary
	double offset = 0;	//!< normal.dot(p) == offset, same frame as the points [m]
	/** RMS orthogonal distance of the points to the line [m]: the square
	 * root of the smaller eigenvalue of their covariance. */
	double rmsResidual = 0;
	size_t n = 0;

	/** Sum of squared orthogonal distances of the points to the line [m^2]. */
	double sumSquaredResiduals() const
	{
		return static_cast<double>(n) * rmsResidual * rmsResidual;
	}

	Eigen::Vector2d direction() const { return {-normal.y(), normal.x()}; }
	double distance(const Eigen::Vector2d& p) const
	{
		return std::abs(normal.dot(p) - offset);
	}
};

/** Orthogonal regression through the points summed in `m`: the normal is the
 * eigenvector of the 2x2 covariance with the smaller eigenvalue
 * (Eigen::SelfAdjointEigenSolver). Coordinates are those of the summed
 * points. With fewer than 2 points the normal is arbitrary. */
LineFit fitLine(const PointMoments& m);

}  // namespace lvf::lines
