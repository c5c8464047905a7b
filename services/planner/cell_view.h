#pragma once

// A view of the plant realised in the cell: the camera wanted at a point of the plant (world)
// frame looking at a target becomes a turntable angle and arm joints. The turntable turns the
// plant so that the view faces the arm (the arm reaches best near its own azimuth), so any view
// direction around the plant is allowed; the arm only has to reach the view's elevation and
// distance. The result is checked against the cell's limits: inverse kinematics inside the joint
// limits, the camera above the turntable top and outside the plant's box by a margin, and, when
// the arm's safety envelope is given, the whole joint move from the current joints as avc-robot
// checks it (table, turntable, plant keep-out), so that the driver never refuses a planned view.

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/cell/cell_model.h"
#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/safety_envelope.h"

namespace avc::planner {

struct CellView {
  double turntable_angle = 0;  // radians
  kinematics::JointVector joints = kinematics::JointVector::Zero();
  camera::Camera camera;  // world (plant) frame
  Eigen::Vector3d centre_world = Eigen::Vector3d::Zero();
};

struct ReachOptions {
  // The camera centre stays this far above the turntable top (world z = 0), metres.
  double table_clearance = 0.05;
  // ... and this far outside `keep_out` (the plant's box), metres.
  double plant_clearance = 0.05;
  // Azimuths tried around the arm's own when it cannot reach a view there, radians.
  std::vector<double> azimuth_offsets = {0, 0.5236, -0.5236, 1.0472, -1.0472};
  // The envelope avc-robot enforces, as kinematics::PlanningEnvelope gives it; unset: the checks
  // above only. The planner sets its plant keep-out from the proxy as it grows, with
  // plant_keep_out_margin (the orchestrator's 2 cm and 5 mm).
  std::optional<kinematics::SafetyEnvelope> envelope;
  double plant_keep_out_margin = 0.025;
};

// nullopt when no turntable angle lets the arm reach the view within the limits above. Throws
// std::invalid_argument for non-finite points or an eye on the target.
std::optional<CellView> RealiseView(const cell::CellModel& cell, const Eigen::Vector3d& eye_world,
                                    const Eigen::Vector3d& target_world,
                                    const Eigen::AlignedBox3d& keep_out,
                                    const kinematics::JointVector& current,
                                    const ReachOptions& options = {});

}  // namespace avc::planner
