#include "core/kinematics/safety_envelope.h"

#include <fmt/format.h>

#include <cmath>

#include "core/geometry/rigid_transform.h"
#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/inverse_kinematics.h"

namespace avc::kinematics {
namespace {

constexpr std::array<const char*, 5> kFrameNames = {"elbow", "wrist 1", "wrist 2", "wrist 3",
                                                    "flange"};

std::string CheckKeepOut(const std::optional<KeepOutCylinder>& cylinder, const Eigen::Vector3d& p,
                         const std::string& name) {
  if (!cylinder || !cylinder->Contains(p)) return {};
  return fmt::format(
      "{} would enter the keep-out cylinder ({:.3f} m from its axis, radius {:.3f} m)", name,
      cylinder->RadialDistance(p), cylinder->radius_m);
}

std::string CheckPlantKeepOut(const PlantKeepOut& plant, const Eigen::Vector3d& p,
                              const std::string& name) {
  if (!plant.Contains(p)) return {};
  return fmt::format(
      "{} would enter the plant's keep-out: {:.3f} m from the turntable axis where the plant "
      "proxy, swept about the axis and with margin, reaches {:.3f} m",
      name, plant.AxisDistance(p), plant.RadiusAt(p));
}

std::string CheckPoint(const SafetyEnvelope& envelope, const Eigen::Vector3d& p,
                       const std::string& name) {
  if (envelope.table_z_base_m && p.z() < *envelope.table_z_base_m + envelope.table_clearance_m) {
    return fmt::format("{} would be at z = {:.3f} m, below the table plane {:.3f} m + {:.3f} m",
                       name, p.z(), *envelope.table_z_base_m, envelope.table_clearance_m);
  }
  if (auto error = CheckKeepOut(envelope.keep_out, p, name); !error.empty()) return error;
  if (auto error = CheckPlantKeepOut(envelope.plant_keep_out, p, name); !error.empty()) {
    return error;
  }
  return {};
}

// Checks the elbow, wrists, flange and tool points at joints q.
std::string CheckPose(const SafetyEnvelope& envelope, const DhParameters& dh,
                      const JointVector& q) {
  for (int i = 0; i < 6; ++i) {
    if (q[i] < envelope.joint_min[i] || q[i] > envelope.joint_max[i]) {
      return fmt::format("joint {} = {:.4f} rad is outside its limits [{:.4f}, {:.4f}]", i + 1,
                         q[i], envelope.joint_min[i], envelope.joint_max[i]);
    }
  }
  const auto frames = JointFrames(dh, q);
  for (size_t f = 2; f < frames.size(); ++f) {
    if (auto error = CheckPoint(envelope, frames[f].translation(), kFrameNames[f - 2]);
        !error.empty()) {
      return error;
    }
  }
  for (size_t t = 0; t < envelope.tool_points_flange.size(); ++t) {
    if (auto error = CheckPoint(envelope, frames[6] * envelope.tool_points_flange[t],
                                fmt::format("tool point {}", t));
        !error.empty()) {
      return error;
    }
  }
  return {};
}

std::string CheckCaps(double speed, double acceleration, double max_speed, double max_acceleration,
                      const char* units) {
  if (!(std::isfinite(speed) && speed > 0 && speed <= max_speed)) {
    return fmt::format("speed {} {} is outside (0, {}]", speed, units, max_speed);
  }
  if (!(std::isfinite(acceleration) && acceleration > 0 && acceleration <= max_acceleration)) {
    return fmt::format("acceleration {} {}/s is outside (0, {}]", acceleration, units,
                       max_acceleration);
  }
  return {};
}

}  // namespace

std::string SafetyEnvelope::Validate() const {
  for (int i = 0; i < 6; ++i) {
    if (!(std::isfinite(joint_min[i]) && std::isfinite(joint_max[i]) &&
          joint_min[i] < joint_max[i])) {
      return fmt::format("joint {} limits [{}, {}] are not an interval", i + 1, joint_min[i],
                         joint_max[i]);
    }
  }
  if (table_z_base_m && !std::isfinite(*table_z_base_m)) return "table_z_base_m is not finite";
  if (!(std::isfinite(table_clearance_m) && table_clearance_m >= 0)) {
    return "table_clearance_m must be finite and 0 or more";
  }
  if (keep_out) {
    if (auto error = keep_out->Validate(); !error.empty()) return "keep_out: " + error;
  }
  if (auto error = plant_keep_out.Validate(); !error.empty()) return error;
  if (!(max_joint_speed_rad_s > 0 && max_joint_acceleration_rad_s2 > 0 &&
        max_linear_speed_m_s > 0 && max_linear_acceleration_m_s2 > 0)) {
    return "speed and acceleration caps must be positive";
  }
  if (path_samples < 2) return "path_samples must be at least 2";
  return {};
}

SafetyEnvelope WithMargin(SafetyEnvelope envelope, double margin_m) {
  envelope.table_clearance_m += margin_m;
  if (envelope.keep_out) {
    envelope.keep_out->radius_m += margin_m;
    envelope.keep_out->z_min_m -= margin_m;
    envelope.keep_out->z_max_m += margin_m;
  }
  return envelope;
}

SafetyEnvelope PlanningEnvelope(const SafetyEnvelope& driver) { return WithMargin(driver, 0.005); }

std::string CheckJointMove(const SafetyEnvelope& envelope, const DhParameters& dh,
                           const JointVector& from, const JointVector& to, double speed,
                           double acceleration) {
  if (auto error = ValidateJoints(to); !error.empty()) return "target: " + error;
  if (!from.allFinite()) return "current joints are not finite";
  if (auto error = CheckCaps(speed, acceleration, envelope.max_joint_speed_rad_s,
                             envelope.max_joint_acceleration_rad_s2, "rad/s");
      !error.empty()) {
    return "joint move " + error;
  }
  for (int s = 1; s <= envelope.path_samples; ++s) {
    const double u = static_cast<double>(s) / envelope.path_samples;
    if (auto error = CheckPose(envelope, dh, from + u * (to - from)); !error.empty()) {
      return fmt::format("joint move at {:.0f}% of the path: {}", 100 * u, error);
    }
  }
  return {};
}

bool JointPathAllowed(const std::optional<SafetyEnvelope>& envelope, const DhParameters& dh,
                      const JointVector& from, const JointVector& to) {
  return !envelope || CheckJointMove(*envelope, dh, from, to, envelope->max_joint_speed_rad_s,
                                     envelope->max_joint_acceleration_rad_s2)
                          .empty();
}

std::string CheckLinearMove(const SafetyEnvelope& envelope, const DhParameters& dh,
                            const JointVector& from, const Eigen::Isometry3d& T_base_flange,
                            double speed, double acceleration, JointVector* target_q) {
  if (auto problem = geometry::RigidTransformProblem(T_base_flange, "target pose");
      !problem.empty()) {
    return problem;
  }
  if (auto error = CheckCaps(speed, acceleration, envelope.max_linear_speed_m_s,
                             envelope.max_linear_acceleration_m_s2, "m/s");
      !error.empty()) {
    return "linear move " + error;
  }
  const Eigen::Isometry3d start = ForwardKinematics(dh, from);
  const Eigen::Quaterniond q0(start.linear()), q1(T_base_flange.linear());
  JointVector q = from;
  for (int s = 1; s <= envelope.path_samples; ++s) {
    const double u = static_cast<double>(s) / envelope.path_samples;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = (1 - u) * start.translation() + u * T_base_flange.translation();
    pose.linear() = q0.slerp(u, q1).normalized().toRotationMatrix();
    const auto next = RefineInverseKinematics(dh, pose, q, 1e-9);
    if (!next) {
      return fmt::format(
          "linear move at {:.0f}% of the path: no inverse kinematics (out of "
          "reach or through a singularity)",
          100 * u);
    }
    q = *next;
    if (auto error = CheckPose(envelope, dh, q); !error.empty()) {
      return fmt::format("linear move at {:.0f}% of the path: {}", 100 * u, error);
    }
  }
  if (target_q) *target_q = q;
  return {};
}

}  // namespace avc::kinematics
