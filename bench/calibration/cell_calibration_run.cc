#include "bench/calibration/cell_calibration_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <numbers>

#include "bench/calibration/hand_eye/hand_eye_comparison.h"
#include "bench/devices/cell_processes.h"
#include "bench/summary.h"
#include "core/bus/bus.h"
#include "core/calibration/cell/calibration_yaml.h"
#include "core/calibration/pipeline/calibrate_cell.h"
#include "core/kinematics/safety_envelope.h"
#include "drivers/client/cell_client.h"
#include "services/calibrator/calibration_collector.h"
#include "sim/cell/cell_fixtures.h"
#include "sim/cell/view_selection.h"
#include "sim/emulators/cell/simulated_cell.h"
#include "sim/scene/chessboard_scene.h"

namespace avc::bench {
namespace {

using std::chrono::milliseconds;
constexpr double kDeg = std::numbers::pi / 180;

nlohmann::json Stats(std::vector<double> values) {
  const Summary summary = Summarize(std::move(values));
  return {{"median", summary.median}, {"p90", summary.p90}, {"max", summary.max}};
}

double RotationDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() / kDeg;
}

}  // namespace

nlohmann::json RunCellCalibration(const CellCalibrationRunOptions& options) {
  const sim::ChessboardSpec board;  // what `--chessboard 9x6` lays on the table
  CellProcessOptions cell_options =
      LocalCellOptions(options.port, "calbench", options.time_scale, options.work_dir);
  cell_options.extra_sim_args = {
      "--chessboard", "9x6",   "--samples",     std::to_string(options.samples),
      "--background", "plain", "--table-sigma", fmt::format("{}", options.table_sigma_deg)};
  cell_options.stages = false;  // a calibration reconstructs nothing
  CellProcesses cell(cell_options);

  bus::Bus bus(ClientBusOptions(cell_options, "avc-bench"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  client::CellClient client(bus, loop, "avc-bench", cell.key());
  try {
    client.WaitReady({"avc-sim"}, milliseconds(30000));
    calibrator::CollectOptions collect;
    collect.folder = options.work_dir / "dataset";
    collect.plan.hand_eye_poses = options.hand_eye_poses;
    collect.plan.table_angles = options.table_angles;
    // CellProcesses' avc-robot enforces the nominal cell's envelope: plan inside it.
    collect.plan.envelope = kinematics::PlanningEnvelope(sim::NominalCellEnvelope());
    const auto progress = [](const std::string& what) { std::cerr << "  " << what << "\n"; };
    const calibration::CalibrationDataset dataset =
        calibrator::CollectCalibrationDataset(client, collect, progress);
    calibration::CalibrationDetails details;
    const calibration::CellCalibration calibration =
        calibration::CalibrateCell(dataset, calibration::CalibrateOptions{}, &details);
    calibration::SaveCalibration(calibration, options.work_dir / "calibration.yaml");

    // The scan path: rings of views around the plant's place, the table stepping a full turn.
    const sim::CellTruth nominal = sim::NominalCell();
    const Eigen::Vector3d target(0, 0, 0.1);
    std::vector<double> centre_mm, rotation_deg;
    // Simulator world to calibrated world, through the board both know.
    const Eigen::Isometry3d T_calworld_simworld =
        calibration.T_table_board * board.T_world_board.inverse();
    for (int ring = 0; ring < options.scan_rings; ++ring) {
      const double elevation = (20 + 30.0 * ring / std::max(1, options.scan_rings - 1)) * kDeg;
      const auto view = sim::FirstReachableView(nominal, target, 0.55, elevation,
                                                sim::RobotAzimuth(nominal), client.last_joints());
      if (!view) throw std::runtime_error(fmt::format("scan ring {} is out of reach", ring));
      client.MoveJoints(view->q, milliseconds(120000));
      for (int k = 0; k < options.scan_angles; ++k) {
        const double angle = 2 * std::numbers::pi * k / options.scan_angles;
        client.TurntableGoto(angle, milliseconds(60000));
        client.WaitFreshState(milliseconds(5000));
        const Eigen::Isometry3d T_base_flange = client.last_flange_pose();
        client.Capture(fmt::format("scan_{}_{}", ring, k), avc::image_t::ENCODING_JPEG,
                       milliseconds(60000));
        const camera::Camera truth = sim::ReadTruthLog(cell.truth_log()).back().camera;
        const Eigen::Isometry3d estimate =
            calibration.CameraAt(T_base_flange, angle).T_cam_world * T_calworld_simworld;
        centre_mm.push_back(
            1000 *
            (estimate.inverse().translation() - truth.T_cam_world.inverse().translation()).norm());
        rotation_deg.push_back(RotationDeg(estimate.linear(), truth.T_cam_world.linear()));
      }
      std::cerr << fmt::format("  scan ring {}/{} done\n", ring + 1, options.scan_rings);
    }
    const calibration::CalibrationResiduals& r = calibration.residuals;
    nlohmann::json result;
    result["calibration"] = {{"intrinsics_rms_px", r.intrinsics_rms_px},
                             {"hand_eye_rms_px", r.hand_eye_rms_px},
                             {"closed_form_rms_px", details.closed_form_rms_px},
                             {"hand_eye_views", details.hand_eye_views},
                             {"turntable_views", details.turntable_views},
                             {"turntable_rms_mm", r.turntable_centre_rms_mm},
                             {"rejected", r.rejected}};
    // Every hand-eye method on the cell's own detections, as on the real set.
    const calibration::CalibrateOptions defaults;
    result["hand_eye_methods"] =
        CompareHandEyeMethods(details.hand_eye_observations, details.hand_eye_board_views,
                              calibration.intrinsics, defaults.diversity, defaults.refinement);
    result["scan"] = {{"views", centre_mm.size()},
                      {"centre_error_mm", Stats(centre_mm)},
                      {"rotation_error_deg", Stats(rotation_deg)},
                      {"table_sigma_deg", options.table_sigma_deg}};
    const double median_centre = result["scan"]["centre_error_mm"]["median"];
    const double median_rotation = result["scan"]["rotation_error_deg"]["median"];
    result["acceptance"] = {{"reprojection_rms_le_0.3px", r.hand_eye_rms_px <= 0.3},
                            {"centre_median_le_0.5mm", median_centre <= 0.5},
                            {"rotation_median_le_0.05deg", median_rotation <= 0.05}};
    return result;
  } catch (const std::exception& error) {
    throw std::runtime_error(fmt::format("{}\n{}", error.what(), cell.LogTails()));
  }
}

}  // namespace avc::bench
