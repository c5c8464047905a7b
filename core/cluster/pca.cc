#include "core/cluster/pca.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace avc::cluster {

double PrincipalAxes::PlaneDeviation() const { return std::sqrt(std::max(0.0, eigenvalues[0])); }

PrincipalAxes FitPrincipalAxes(const std::vector<Eigen::Vector3f>& points,
                               const std::vector<uint32_t>& indices) {
  if (indices.empty()) throw std::invalid_argument("FitPrincipalAxes: no points");
  PrincipalAxes result;
  for (uint32_t i : indices) result.centroid += points[i].cast<double>();
  result.centroid /= static_cast<double>(indices.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (uint32_t i : indices) {
    const Eigen::Vector3d d = points[i].cast<double>() - result.centroid;
    covariance.noalias() += d * d.transpose();
  }
  covariance /= static_cast<double>(indices.size());
  // Closed form 3x3 solver: fast and deterministic; accurate enough for plane fits.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  result.eigenvalues = solver.eigenvalues();
  result.axes = solver.eigenvectors();
  return result;
}

}  // namespace avc::cluster
