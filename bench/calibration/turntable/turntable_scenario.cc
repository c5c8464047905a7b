#include "bench/calibration/turntable/turntable_scenario.h"

#include <cmath>

#include "core/util/ordered_draws.h"
#include "sim/cell/cell_truth.h"

namespace avc::bench {
namespace {

Eigen::Matrix3d RotationFromVector(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle == 0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

}  // namespace

calibration::TurntableAxis TurntableScenario::TruthInFixedFrame() const {
  calibration::TurntableAxis truth;
  truth.axis = T_fixed_table.linear() * axis_table;
  const Eigen::Vector3d origin = T_table_board0.translation();
  const Eigen::Vector3d foot = centre_table + axis_table * axis_table.dot(origin - centre_table);
  truth.centre = T_fixed_table * foot;
  return truth;
}

TurntableScenario RandomTurntableScenario(sim::DeterministicRandom& random, double axis_tilt,
                                          double board_offset) {
  TurntableScenario scenario;
  const double tilt_direction = random.Uniform(0, 2 * M_PI);
  scenario.axis_table = Eigen::AngleAxisd(axis_tilt, Eigen::Vector3d(std::cos(tilt_direction),
                                                                     std::sin(tilt_direction), 0))
                            .toRotationMatrix() *
                        Eigen::Vector3d::UnitZ();
  const double centre_y = random.Symmetric(0.005);  // y before x, as in util::DrawVector3
  scenario.centre_table = Eigen::Vector3d(random.Symmetric(0.005), centre_y, 0);

  // The board flat on the table, origin board_offset from the axis in a random direction, turned
  // randomly in its plane.
  const double azimuth = random.Uniform(0, 2 * M_PI);
  scenario.T_table_board0.linear() =
      Eigen::AngleAxisd(random.Uniform(0, 2 * M_PI), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  scenario.T_table_board0.translation() =
      scenario.centre_table +
      board_offset * Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), 0);

  // A camera 0.5 m from the table centre at a random azimuth and 30-60 deg elevation, looking at
  // the centre (OpenCV camera axes: z forward, y down in the image).
  const double view_azimuth = random.Uniform(0, 2 * M_PI);
  const double elevation = random.Uniform(M_PI / 6, M_PI / 3);
  const Eigen::Vector3d eye =
      0.5 * Eigen::Vector3d(std::cos(elevation) * std::cos(view_azimuth),
                            std::cos(elevation) * std::sin(view_azimuth), std::sin(elevation));
  const Eigen::Vector3d forward = -eye.normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Isometry3d T_table_fixed = Eigen::Isometry3d::Identity();
  T_table_fixed.linear() << right, down, forward;
  T_table_fixed.translation() = eye;
  scenario.T_fixed_table = T_table_fixed.inverse();
  return scenario;
}

std::vector<calibration::TurntableView> SimulateTurntableViews(const TurntableScenario& scenario,
                                                               int angles,
                                                               const TurntableNoise& noise,
                                                               sim::DeterministicRandom& random) {
  sim::CellTruth cell;
  cell.turntable_axis_table = scenario.axis_table;
  cell.turntable_centre_table = scenario.centre_table;
  std::vector<calibration::TurntableView> views;
  for (int k = 0; k < angles; ++k) {
    calibration::TurntableView view;
    view.angle = 2 * M_PI * k / angles;
    const double true_angle = view.angle + noise.angle_sigma * random.Normal();
    // The board rides the world frame, which equals the table frame at angle 0.
    view.T_fixed_board =
        scenario.T_fixed_table * sim::TableFromWorld(cell, true_angle) * scenario.T_table_board0;
    const Eigen::Vector3d position_noise =
        util::DrawVector3<Eigen::Vector3d>([&] { return random.Normal(); });
    const Eigen::Vector3d rotation_noise =
        util::DrawVector3<Eigen::Vector3d>([&] { return random.Normal(); });
    view.T_fixed_board.translation() += noise.position_sigma * position_noise;
    view.T_fixed_board.linear() =
        view.T_fixed_board.linear() * RotationFromVector(noise.orientation_sigma * rotation_noise);
    views.push_back(view);
  }
  return views;
}

double AxisError(const calibration::TurntableAxis& estimate,
                 const calibration::TurntableAxis& truth) {
  const double cosine = estimate.axis.normalized().dot(truth.axis.normalized());
  // atan2 of |cross| and dot keeps precision for tiny angles, where acos does not.
  return std::atan2(estimate.axis.normalized().cross(truth.axis.normalized()).norm(), cosine);
}

double CentreError(const calibration::TurntableAxis& estimate,
                   const calibration::TurntableAxis& truth) {
  return (estimate.centre - truth.centre).norm();
}

}  // namespace avc::bench
