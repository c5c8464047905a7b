#include "bench/clustering/baselines/input_checks.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::cluster::baselines {

void CheckPoints(const PointSet& set, std::string_view method) {
  if (set.points.empty()) {
    throw std::invalid_argument(fmt::format("{}: point set '{}' is empty", method, set.name));
  }
  for (size_t i = 0; i < set.points.size(); ++i) {
    if (!set.points[i].allFinite()) {
      throw std::invalid_argument(
          fmt::format("{}: point {} of set '{}' is not finite", method, i, set.name));
    }
  }
}

void CheckNormals(const PointSet& set, std::string_view method) {
  if (set.normals.size() != set.points.size()) {
    throw std::invalid_argument(fmt::format("{}: set '{}' has {} normals for {} points", method,
                                            set.name, set.normals.size(), set.points.size()));
  }
  for (size_t i = 0; i < set.normals.size(); ++i) {
    if (!set.normals[i].allFinite() || set.normals[i].squaredNorm() == 0.0f) {
      throw std::invalid_argument(
          fmt::format("{}: normal {} of set '{}' is not finite or zero", method, i, set.name));
    }
  }
}

void CheckClusterCount(int clusters, size_t points, std::string_view method) {
  if (clusters < 1 || static_cast<size_t>(clusters) > points) {
    throw std::invalid_argument(
        fmt::format("{}: cluster count {} must be in [1, {}] (the number of points)", method,
                    clusters, points));
  }
}

}  // namespace avc::cluster::baselines
