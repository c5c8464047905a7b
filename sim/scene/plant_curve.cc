#include <cmath>

#include "sim/scene/plant_plan.h"

namespace avc::sim {

Eigen::Vector3f Heading(float azimuth, float elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
          std::sin(elevation)};
}

void ArcCurve(const Eigen::Vector3f& start, float azimuth, float elevation, float droop,
              float droop_power, float side_bend, float length, int segments,
              std::vector<Eigen::Vector3f>* points, std::vector<Eigen::Vector3f>* tangents) {
  auto direction = [&](float t) {
    return Heading(azimuth + side_bend * t, elevation - droop * std::pow(t, droop_power));
  };
  points->assign(1, start);
  if (tangents != nullptr) tangents->assign(1, direction(0.0f));
  const float step = length / static_cast<float>(segments);
  for (int i = 1; i <= segments; ++i) {
    // Midpoint rule: the chord follows the direction halfway along the step.
    const float t_mid = (static_cast<float>(i) - 0.5f) / static_cast<float>(segments);
    points->push_back(points->back() + step * direction(t_mid));
    if (tangents != nullptr) tangents->push_back(direction(static_cast<float>(i) / segments));
  }
}

}  // namespace avc::sim
