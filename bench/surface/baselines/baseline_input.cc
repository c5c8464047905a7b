#include "bench/surface/baselines/baseline_input.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/cluster/data_scale.h"

namespace avc::surface::baselines {

void CheckBaselineInput(const geometry::PointCloud& cloud, std::string_view method,
                        bool require_normals) {
  if (cloud.size() < 3) {
    throw std::invalid_argument(
        fmt::format("{}: needs at least 3 points, got {}", method, cloud.size()));
  }
  if (const std::string problem = cloud.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("{}: {}", method, problem));
  }
  if (require_normals && cloud.normals.empty()) {
    throw std::invalid_argument(
        fmt::format("{}: needs oriented normals, the cloud has none", method));
  }
}

double ResolveSpacing(const geometry::PointCloud& cloud, double spacing, std::string_view method) {
  if (spacing > 0.0) return spacing;
  try {
    return cluster::EstimateDataScale(cloud.positions).spacing;
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(
        fmt::format("{}: cannot measure the point spacing ({})", method, error.what()));
  }
}

}  // namespace avc::surface::baselines
