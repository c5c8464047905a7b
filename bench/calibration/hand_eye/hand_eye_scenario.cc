#include "bench/calibration/hand_eye/hand_eye_scenario.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <optional>
#include <stdexcept>

#include "core/kinematics/inverse_kinematics.h"
#include "core/util/validation.h"
#include "sim/cell/cell_truth.h"
#include "sim/cell/perturbation.h"
#include "sim/cell/random.h"
#include "sim/cell/view_selection.h"

namespace avc::bench {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr int kMaxAttemptsPerPose = 500;
constexpr double kImageMarginPx = 10;

Eigen::Vector3d NormalVector(sim::DeterministicRandom& random) {
  const double x = random.Normal(), y = random.Normal(), z = random.Normal();
  return {x, y, z};
}

Eigen::Isometry3d WithRobotNoise(const Eigen::Isometry3d& pose, const HandEyeScenarioOptions& o,
                                 sim::DeterministicRandom& random) {
  const Eigen::Vector3d rotation = o.robot_rotation_sigma_deg * kDegree * NormalVector(random);
  const Eigen::Vector3d translation = o.robot_translation_sigma_mm * 1e-3 * NormalVector(random);
  Eigen::Isometry3d noisy = pose;
  if (rotation.norm() > 0) {
    noisy.linear() = Eigen::AngleAxisd(rotation.norm(), rotation.normalized()) * pose.linear();
  }
  noisy.translation() += translation;
  return noisy;
}

cv::Mat CameraMatrix(const camera::Intrinsics& k) {
  return (cv::Mat_<double>(3, 3) << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
}

Eigen::Isometry3d SolveBoardPose(const std::vector<Eigen::Vector3d>& board_points,
                                 const std::vector<Eigen::Vector2d>& pixels,
                                 const camera::Intrinsics& k) {
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  for (size_t i = 0; i < pixels.size(); ++i) {
    object.emplace_back(board_points[i].x(), board_points[i].y(), board_points[i].z());
    image.emplace_back(pixels[i].x(), pixels[i].y());
  }
  cv::Mat distortion(1, 5, CV_64F);
  for (int i = 0; i < 5; ++i) distortion.at<double>(i) = k.distortion[static_cast<size_t>(i)];
  cv::Mat rvec, tvec;
  if (!cv::solvePnP(object, image, CameraMatrix(k), distortion, rvec, tvec, false,
                    cv::SOLVEPNP_ITERATIVE)) {
    throw std::runtime_error("hand-eye scenario: solvePnP failed");
  }
  // Polish to convergence: solvePnP stops after a fixed number of iterations.
  cv::solvePnPRefineLM(
      object, image, CameraMatrix(k), distortion, rvec, tvec,
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-15));
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  Eigen::Isometry3d T_cam_board = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) T_cam_board.linear()(r, c) = rotation.at<double>(r, c);
    T_cam_board.translation()(r) = tvec.at<double>(r);
  }
  return T_cam_board;
}

// The corners' pixels when every one is in front of the camera and inside the image margin.
std::optional<std::vector<Eigen::Vector2d>> VisibleCorners(
    const std::vector<Eigen::Vector3d>& board_points, const Eigen::Isometry3d& T_cam_board,
    const camera::Intrinsics& k) {
  std::vector<Eigen::Vector2d> pixels;
  for (const Eigen::Vector3d& point : board_points) {
    const auto pixel = k.Project(T_cam_board * point);
    if (!pixel || pixel->x() < kImageMarginPx || pixel->y() < kImageMarginPx ||
        pixel->x() > k.width - 1 - kImageMarginPx || pixel->y() > k.height - 1 - kImageMarginPx) {
      return std::nullopt;
    }
    pixels.push_back(*pixel);
  }
  return pixels;
}

}  // namespace

std::string HandEyeScenarioOptions::Validate() const {
  const HandEyeScenarioOptions& o = *this;
  const bool valid = o.poses >= 1 && o.board_columns >= 2 && o.board_rows >= 2 && o.square_m > 0 &&
                     o.pixel_sigma_px >= 0 && o.robot_rotation_sigma_deg >= 0 &&
                     o.robot_translation_sigma_mm >= 0 && o.min_distance_m > 0 &&
                     o.max_distance_m >= o.min_distance_m &&
                     o.max_elevation_deg >= o.min_elevation_deg && o.azimuth_half_range_deg >= 0 &&
                     o.roll_half_range_deg >= 0;
  if (!valid) return "hand-eye scenario: invalid options";
  if (o.intrinsics) {
    if (std::string error = o.intrinsics->Validate(); !error.empty()) {
      return "hand-eye scenario: camera " + error;
    }
  }
  return {};
}

std::vector<calibration::hand_eye::HandEyeObservation> HandEyeScenario::Observations() const {
  std::vector<calibration::hand_eye::HandEyeObservation> observations;
  for (const HandEyeSyntheticView& view : views) {
    observations.push_back({view.T_base_flange, view.T_cam_board});
  }
  return observations;
}

std::vector<calibration::hand_eye::HandEyeObservation> HandEyeScenario::TrueObservations() const {
  std::vector<calibration::hand_eye::HandEyeObservation> observations;
  for (const HandEyeSyntheticView& view : views) {
    observations.push_back({view.true_T_base_flange, view.true_T_cam_board});
  }
  return observations;
}

std::vector<calibration::hand_eye::BoardView> HandEyeScenario::BoardViews() const {
  std::vector<calibration::hand_eye::BoardView> board_views;
  for (const HandEyeSyntheticView& view : views) {
    board_views.push_back({view.T_base_flange, board_points, view.pixels});
  }
  return board_views;
}

HandEyeScenario MakeHandEyeScenario(const HandEyeScenarioOptions& options, uint64_t seed) {
  RequireValid(options);
  // The cell's hand-eye and base placement vary with the seed; the intrinsics are given (taken
  // as already calibrated).
  const sim::CellTruth cell = sim::PerturbedCell(static_cast<uint32_t>(seed ^ (seed >> 32)));
  sim::DeterministicRandom random(seed);
  HandEyeScenario scenario;
  scenario.intrinsics = options.intrinsics.value_or(sim::NominalCell().intrinsics);
  scenario.true_T_flange_cam = cell.T_flange_cam;

  for (int row = 0; row < options.board_rows; ++row) {
    for (int column = 0; column < options.board_columns; ++column) {
      scenario.board_points.emplace_back(column * options.square_m, row * options.square_m, 0);
    }
  }
  // The board lies flat on the table, its centre within 3 cm of the table centre, any yaw.
  const Eigen::Vector3d board_centre_board((options.board_columns - 1) * options.square_m / 2,
                                           (options.board_rows - 1) * options.square_m / 2, 0);
  // y drawn before x, as in util::DrawVector3.
  const double board_centre_y = random.Symmetric(0.03);
  const Eigen::Vector3d board_centre_table(random.Symmetric(0.03), board_centre_y, 0);
  const Eigen::Isometry3d T_table_board =
      Eigen::Translation3d(board_centre_table) *
      Eigen::AngleAxisd(random.Uniform(0, 2 * std::numbers::pi), Eigen::Vector3d::UnitZ()) *
      Eigen::Translation3d(-board_centre_board);
  scenario.true_T_base_board = cell.T_base_table * T_table_board;

  const Eigen::Vector3d robot_base_table = cell.T_base_table.inverse().translation();
  const double robot_azimuth = sim::RobotAzimuth(cell);
  const kinematics::DhParameters nominal_arm = kinematics::NominalUr5();
  const Eigen::Isometry3d T_cam_flange = cell.T_flange_cam.inverse();
  for (int pose = 0; pose < options.poses; ++pose) {
    bool found = false;
    for (int attempt = 0; attempt < kMaxAttemptsPerPose && !found; ++attempt) {
      const double distance = random.Uniform(options.min_distance_m, options.max_distance_m);
      const double elevation =
          random.Uniform(options.min_elevation_deg, options.max_elevation_deg) * kDegree;
      const double azimuth =
          robot_azimuth + random.Symmetric(options.azimuth_half_range_deg) * kDegree;
      const double roll = random.Symmetric(options.roll_half_range_deg) * kDegree;
      const double target_y = random.Symmetric(0.02);
      const Eigen::Vector3d target =
          board_centre_table + Eigen::Vector3d(random.Symmetric(0.02), target_y, 0);
      const Eigen::Vector3d centre = sim::ViewpointOnSphere(target, distance, elevation, azimuth);
      const Eigen::Isometry3d T_table_cam = sim::LookAtPose(centre, target, robot_base_table) *
                                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ());
      const Eigen::Isometry3d T_base_flange = cell.T_base_table * T_table_cam * T_cam_flange;
      if (kinematics::InverseKinematics(nominal_arm, T_base_flange).empty()) continue;
      const Eigen::Isometry3d T_cam_board = T_table_cam.inverse() * T_table_board;
      const auto pixels = VisibleCorners(scenario.board_points, T_cam_board, scenario.intrinsics);
      if (!pixels) continue;

      HandEyeSyntheticView view;
      view.true_T_base_flange = T_base_flange;
      view.true_T_cam_board = T_cam_board;
      view.T_base_flange = WithRobotNoise(T_base_flange, options, random);
      for (const Eigen::Vector2d& pixel : *pixels) {
        const double du = random.Normal(), dv = random.Normal();
        view.pixels.push_back(pixel + options.pixel_sigma_px * Eigen::Vector2d(du, dv));
      }
      view.T_cam_board = SolveBoardPose(scenario.board_points, view.pixels, scenario.intrinsics);
      scenario.views.push_back(std::move(view));
      found = true;
    }
    if (!found) {
      throw std::runtime_error(fmt::format(
          "hand-eye scenario: no reachable view seeing the whole board for pose {} (seed {})", pose,
          seed));
    }
  }
  return scenario;
}

}  // namespace avc::bench
