#include "core/mvs/mvs_points.h"

#include <fmt/format.h>

#include <algorithm>

namespace avc::mvs {

std::string MvsPoints::Validate() const {
  if (std::string problem = cloud.Validate(); !problem.empty()) return problem;
  const size_t n = cloud.size();
  if (cloud.normals.size() != n)
    return fmt::format("{} normals for {} points", cloud.normals.size(), n);
  if (cloud.colors.size() != n)
    return fmt::format("{} colours for {} points", cloud.colors.size(), n);
  if (confidence.size() != n)
    return fmt::format("{} confidences for {} points", confidence.size(), n);
  if (views.size() != n) return fmt::format("{} view lists for {} points", views.size(), n);
  for (size_t i = 0; i < n; ++i) {
    if (!(confidence[i] >= 0.0f && confidence[i] <= 1.0f)) {
      return fmt::format("point {}: confidence {} is outside 0..1", i, confidence[i]);
    }
    if (!std::is_sorted(views[i].begin(), views[i].end()) ||
        std::adjacent_find(views[i].begin(), views[i].end()) != views[i].end()) {
      return fmt::format("point {}: its view list is not sorted and unique", i);
    }
  }
  return {};
}

}  // namespace avc::mvs
