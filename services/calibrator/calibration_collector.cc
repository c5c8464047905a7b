#include "services/calibrator/calibration_collector.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

namespace avc::calibrator {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

void SaveImage(const avc::image_t& image, const fs::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(image.data.data()),
            static_cast<std::streamsize>(image.data.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

calibration::CalibrationDataset CollectCalibrationDataset(
    client::CellClient& cell, const CollectOptions& options,
    const std::function<void(const std::string&)>& progress) {
  const auto report = [&](const std::string& what) {
    if (progress) progress(what);
  };
  if (fs::exists(options.folder / "dataset.json")) {
    throw std::runtime_error(options.folder.string() +
                             " already holds a dataset; choose a new folder");
  }
  fs::create_directories(options.folder / "images");

  report("waiting for avc-robot, avc-turntable and avc-camera");
  cell.WaitReady({"avc-robot", "avc-turntable", "avc-camera"}, milliseconds(30000));
  cell.Robot(avc::robot_command_t::KIND_POWER_ON, milliseconds(60000));
  cell.Robot(avc::robot_command_t::KIND_BRAKE_RELEASE, milliseconds(60000));
  cell.TurntableGoto(0, milliseconds(60000));
  cell.WaitFreshState(milliseconds(5000));

  calibration::ChessboardSpec spec;
  spec.inner_cols = options.board.cols;
  spec.inner_rows = options.board.rows;
  spec.square_m = options.board.square_size;
  spec.T_world_board = calibration::ChessboardSpec::DefaultBoardPose(
      spec.inner_cols, spec.inner_rows, spec.square_m);
  const CalibrationPlan plan =
      PlanCalibration(options.planning_cell, spec, cell.last_joints(), options.plan);

  calibration::CalibrationDataset dataset;
  dataset.folder = options.folder;
  dataset.board = options.board;
  const auto shoot = [&](const std::string& name, calibration::ShotPurpose purpose, double angle) {
    cell.WaitFreshState(milliseconds(5000));  // the pose the arm settled at
    const Eigen::Isometry3d T_base_flange = cell.last_flange_pose();
    const client::CapturedView view =
        cell.Capture(name, avc::image_t::ENCODING_PNG, milliseconds(60000));
    const std::string image = "images/" + name + ".png";
    SaveImage(view.image, options.folder / image);
    dataset.shots.push_back({image, purpose, angle, T_base_flange});
  };
  for (size_t i = 0; i < plan.hand_eye.size(); ++i) {
    report(fmt::format("hand-eye pose {}/{}", i + 1, plan.hand_eye.size()));
    cell.MoveJoints(plan.hand_eye[i], milliseconds(120000));
    shoot(fmt::format("hand_eye_{:04d}", i), calibration::ShotPurpose::kHandEye, 0);
  }
  cell.MoveJoints(plan.turntable_pose, milliseconds(120000));
  for (size_t k = 0; k < plan.table_angles.size(); ++k) {
    report(fmt::format("table angle {}/{}", k + 1, plan.table_angles.size()));
    cell.TurntableGoto(plan.table_angles[k], milliseconds(60000));
    shoot(fmt::format("turntable_{:04d}", k), calibration::ShotPurpose::kTurntable,
          plan.table_angles[k]);
  }
  cell.TurntableGoto(0, milliseconds(60000));
  calibration::SaveCalibrationDataset(dataset);
  return dataset;
}

}  // namespace avc::calibrator
