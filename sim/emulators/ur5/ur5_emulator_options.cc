#include "sim/emulators/ur5/ur5_emulator_options.h"

#include <fmt/format.h>

namespace avc::sim::ur5 {

std::string Ur5EmulatorOptions::Validate() const {
  if (auto error = cell.Validate(); !error.empty()) return "cell: " + error;
  if (max_protocol_version < 1 || max_protocol_version > 2) {
    return fmt::format("max_protocol_version {} is not 1 or 2", max_protocol_version);
  }
  if (!(control_frequency > 0 && control_frequency <= 1000)) {
    return fmt::format("control_frequency {} is outside (0, 1000] Hz", control_frequency);
  }
  if (!(encoder_noise_rad >= 0 && encoder_noise_rad < 0.01)) {
    return fmt::format("encoder_noise_rad {} is outside [0, 0.01)", encoder_noise_rad);
  }
  if (auto error = kinematics::ValidateJoints(initial_q); !error.empty()) {
    return "initial_q: " + error;
  }
  return {};
}

}  // namespace avc::sim::ur5
