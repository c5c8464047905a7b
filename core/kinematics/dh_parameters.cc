#include "core/kinematics/dh_parameters.h"

#include <fmt/format.h>

#include <cmath>

namespace avc::kinematics {
namespace {

std::string FirstNonFinite(const JointVector& values, const char* name) {
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(values[i])) return fmt::format("DH {}[{}] is not finite", name, i + 1);
  }
  return {};
}

}  // namespace

std::string DhParameters::Validate() const {
  for (const auto& [values, name] :
       {std::pair{&a, "a"}, std::pair{&d, "d"}, std::pair{&alpha, "alpha"},
        std::pair{&theta_offset, "theta_offset"}}) {
    if (std::string error = FirstNonFinite(*values, name); !error.empty()) return error;
  }
  return {};
}

DhParameters NominalUr5() {
  constexpr double kHalfPi = std::numbers::pi / 2;
  DhParameters dh;
  dh.a << 0, -0.425, -0.39225, 0, 0, 0;
  dh.d << 0.089159, 0, 0, 0.10915, 0.09465, 0.0823;
  dh.alpha << kHalfPi, 0, 0, kHalfPi, -kHalfPi, 0;
  return dh;
}

double WrapAngle(double angle) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  double wrapped = std::remainder(angle, kTwoPi);  // [-pi, pi]
  if (wrapped <= -std::numbers::pi) wrapped += kTwoPi;
  return wrapped;
}

JointVector WrapJoints(const JointVector& q) {
  JointVector wrapped;
  for (int i = 0; i < 6; ++i) wrapped[i] = WrapAngle(q[i]);
  return wrapped;
}

bool WithinJointLimits(const JointVector& q) {
  for (int i = 0; i < 6; ++i) {
    if (!(std::abs(q[i]) <= kJointLimitRad)) return false;
  }
  return true;
}

std::string ValidateJoints(const JointVector& q) {
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(q[i])) return fmt::format("joint {} is not finite", i + 1);
    if (std::abs(q[i]) > kJointLimitRad) {
      return fmt::format("joint {} = {} rad is beyond the +-2 pi limit", i + 1, q[i]);
    }
  }
  return {};
}

}  // namespace avc::kinematics
