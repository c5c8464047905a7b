#include "bench/nbv/baseline_views.h"

#include <cmath>

#include "sim/cell/random.h"
#include "sim/cell/view_selection.h"

namespace avc::planner {
namespace {

Eigen::Vector3d Eye(const BaselineFrame& frame, double distance, double elevation, double azimuth) {
  return frame.aim + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                                std::cos(elevation) * std::sin(azimuth),
                                                std::sin(elevation));
}

// One ring of views; `joints` carries the arm's branch from view to view.
void AppendRing(const sim::CellTruth& cell, const BaselineFrame& frame, double elevation, int count,
                kinematics::JointVector* joints, std::vector<CellView>* views) {
  for (int n = 0; n < count; ++n) {
    const double azimuth = 2 * M_PI * n / count;
    const auto view =
        RealiseView(cell, Eye(frame, frame.distance, elevation, azimuth), frame.aim, {}, *joints);
    if (!view) continue;
    *joints = view->joints;
    views->push_back(*view);
  }
}

}  // namespace

std::vector<CellView> StaticCameraViews(const sim::CellTruth& cell, const BaselineFrame& frame,
                                        double elevation, int count) {
  std::vector<CellView> views;
  kinematics::JointVector joints = sim::StartJoints(cell);
  AppendRing(cell, frame, elevation, count, &joints, &views);
  return views;
}

std::vector<CellView> TwoStaticCameraViews(const sim::CellTruth& cell, const BaselineFrame& frame,
                                           double low, double high, int count) {
  std::vector<CellView> views;
  kinematics::JointVector joints = sim::StartJoints(cell);
  AppendRing(cell, frame, low, count / 2, &joints, &views);
  AppendRing(cell, frame, high, count - count / 2, &joints, &views);
  return views;
}

std::vector<CellView> SphereViews(const sim::CellTruth& cell, const BaselineFrame& frame,
                                  const std::vector<double>& elevations, int azimuths) {
  std::vector<CellView> views;
  const kinematics::JointVector start = sim::StartJoints(cell);
  for (const double elevation : elevations) {
    for (int a = 0; a < azimuths; ++a) {
      const double azimuth = 2 * M_PI * a / azimuths;
      const auto view =
          RealiseView(cell, Eye(frame, frame.distance, elevation, azimuth), frame.aim, {}, start);
      if (view) views.push_back(*view);
    }
  }
  return views;
}

std::vector<CellView> RandomViews(const sim::CellTruth& cell, const BaselineFrame& frame, int count,
                                  uint64_t seed) {
  sim::DeterministicRandom random(seed);
  std::vector<CellView> views;
  kinematics::JointVector joints = sim::StartJoints(cell);
  const double low = std::sin(5 * M_PI / 180);
  const double high = std::sin(75 * M_PI / 180);
  for (int draws = 0; static_cast<int>(views.size()) < count && draws < 50 * count; ++draws) {
    // Uniform on the sphere between the two elevations: uniform in sin(elevation).
    const double elevation = std::asin(random.Uniform(low, high));
    const double azimuth = random.Uniform(0, 2 * M_PI);
    const double distance = frame.distance * random.Uniform(0.9, 1.1);
    const auto view =
        RealiseView(cell, Eye(frame, distance, elevation, azimuth), frame.aim, {}, joints);
    if (!view) continue;
    joints = view->joints;
    views.push_back(*view);
  }
  return views;
}

}  // namespace avc::planner
