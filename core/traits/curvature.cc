#include "core/traits/curvature.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace avc::traits {
namespace {

double Cotangent(const Eigen::Vector3d& at, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - at;
  const Eigen::Vector3d v = b - at;
  const double sine = u.cross(v).norm();
  return sine > 0.0 ? u.dot(v) / sine : 0.0;
}

double Percentile(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  const double position = fraction * static_cast<double>(values.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(values.size() - 1, below + 1);
  const double t = position - static_cast<double>(below);
  return values[below] * (1.0 - t) + values[above] * t;
}

}  // namespace

CurvatureSummary SummarizeMeanCurvature(const geometry::Mesh& mesh) {
  const size_t n = mesh.vertices.size();
  std::vector<Eigen::Vector3d> laplacian(n, Eigen::Vector3d::Zero());
  std::vector<double> area(n, 0.0);
  std::map<std::pair<int, int>, int> edge_faces;
  for (const Eigen::Vector3i& t : mesh.faces) {
    const Eigen::Vector3d p[3] = {mesh.vertices[t[0]].cast<double>(),
                                  mesh.vertices[t[1]].cast<double>(),
                                  mesh.vertices[t[2]].cast<double>()};
    const double face_area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3;
      const int j = (k + 2) % 3;
      // The angle at corner k weighs the opposite edge (i, j).
      const double w = 0.5 * Cotangent(p[k], p[i], p[j]);
      laplacian[t[i]] += w * (p[j] - p[i]);
      laplacian[t[j]] += w * (p[i] - p[j]);
      area[t[k]] += face_area / 3.0;
      ++edge_faces[{std::min(t[i], t[j]), std::max(t[i], t[j])}];
    }
  }
  std::vector<bool> boundary(n, false);
  for (const auto& [edge, count] : edge_faces) {
    if (count != 2) boundary[edge.first] = boundary[edge.second] = true;
  }
  CurvatureSummary summary;
  std::vector<double> values;
  double weighted = 0.0;
  double total_area = 0.0;
  for (size_t v = 0; v < n; ++v) {
    if (boundary[v] || !(area[v] > 0.0)) continue;
    // Laplace-Beltrami of the position is -2 H n.
    const double h = laplacian[v].norm() / (2.0 * area[v]);
    values.push_back(h);
    weighted += h * area[v];
    total_area += area[v];
  }
  summary.vertices = values.size();
  if (values.empty()) return summary;
  summary.mean = weighted / total_area;
  summary.median = Percentile(values, 0.5);
  summary.p90 = Percentile(values, 0.9);
  return summary;
}

}  // namespace avc::traits
