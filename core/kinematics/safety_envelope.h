#pragma once

// Where the arm may go: joint limits, a table plane the links stay above, a fixed keep-out
// cylinder (the turntable) and one around the plant proxy, and speed/acceleration caps. Moves are
// checked along their whole path (sampled): movej's straight joint-space line, movel's straight
// tool line through nominal IK. Pure geometry on the nominal kinematics; no LCM, no sockets.
// avc-robot enforces it on every motion command; the planner checks its views with the same
// rules, so that it only chooses moves the driver will make.

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/keep_out.h"
#include "core/kinematics/plant_keep_out.h"

namespace avc::kinematics {

struct SafetyEnvelope {
  JointVector joint_min = JointVector::Constant(-kJointLimitRad);
  JointVector joint_max = JointVector::Constant(kJointLimitRad);
  // Every checked point keeps z >= table_z_base_m + table_clearance_m (base frame, z up).
  std::optional<double> table_z_base_m;
  double table_clearance_m = 0.02;
  std::optional<KeepOutCylinder> keep_out;  // fixed, from the configuration
  // The plant's, set by the orchestrator as the plant proxy grows (robot_command_t
  // KIND_SET_PLANT_KEEP_OUT); empty until then.
  PlantKeepOut plant_keep_out;
  // Points on the tool (flange frame) checked besides the elbow, wrists and flange: e.g. the
  // camera body's corners.
  std::vector<Eigen::Vector3d> tool_points_flange;
  double max_joint_speed_rad_s = 1.05;
  double max_joint_acceleration_rad_s2 = 1.4;
  double max_linear_speed_m_s = 0.25;
  double max_linear_acceleration_m_s2 = 1.2;
  int path_samples = 32;

  // Empty when usable, else the first bad field.
  std::string Validate() const;
};

// The envelope grown by margin_m: more table clearance, a wider and taller keep-out cylinder
// (the plant keep-out is left as it is). For a planner whose joints differ from the arm's a
// little, so that its moves pass the driver's check of the real joints.
SafetyEnvelope WithMargin(SafetyEnvelope envelope, double margin_m);

// The driver's envelope as a planner of moves (views, calibration poses) checks them: grown by
// 5 mm for the arm's repeatability and the difference between planned and reported joints.
SafetyEnvelope PlanningEnvelope(const SafetyEnvelope& driver);

// Empty when the straight joint-space move from `from` to `to` stays inside the envelope at the
// given speed and acceleration; else the reason, naming the joint, point or cap.
std::string CheckJointMove(const SafetyEnvelope& envelope, const DhParameters& dh,
                           const JointVector& from, const JointVector& to, double speed,
                           double acceleration);

// For planners of moves (views, calibration poses), which choose their own speed: true when no
// envelope is given or the joint-space path from `from` to `to` passes CheckJointMove at the
// envelope's own caps.
bool JointPathAllowed(const std::optional<SafetyEnvelope>& envelope, const DhParameters& dh,
                      const JointVector& from, const JointVector& to);

// The same for a straight tool move to T_base_flange; on success `target_q` (when given) holds
// the IK solution nearest `from` that the move ends at.
std::string CheckLinearMove(const SafetyEnvelope& envelope, const DhParameters& dh,
                            const JointVector& from, const Eigen::Isometry3d& T_base_flange,
                            double speed, double acceleration, JointVector* target_q = nullptr);

}  // namespace avc::kinematics
