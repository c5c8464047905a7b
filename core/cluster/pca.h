#pragma once

// Principal component analysis of a subset of points (the normal constraint's plane fit).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace avc::cluster {

struct PrincipalAxes {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  // Eigenvalues of the covariance, ascending: lambda_min, lambda_mid, lambda_max (m^2).
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();
  // Columns: the matching unit eigenvectors; column 0 is the regression plane's normal, column 2
  // the longest axis.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();

  Eigen::Vector3d PlaneNormal() const { return axes.col(0); }
  Eigen::Vector3d LongestAxis() const { return axes.col(2); }
  // RMS distance of the points to the regression plane (m).
  double PlaneDeviation() const;
};

// PCA of points[indices]; indices must not be empty.
PrincipalAxes FitPrincipalAxes(const std::vector<Eigen::Vector3f>& points,
                               const std::vector<uint32_t>& indices);

}  // namespace avc::cluster
