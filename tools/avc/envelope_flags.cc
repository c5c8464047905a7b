#include "tools/avc/envelope_flags.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace avc::cli {

void AddEnvelopeFlags(CLI::App* command, EnvelopeFlags* flags) {
  // The same flags and meaning in avc robot, avc scan and avc calibrate.
  const char* group = "Safety envelope (give avc robot, avc scan and avc calibrate the same)";
  command
      ->add_option("--table-z", flags->table_z,
                   "the bench's height in the robot's base frame, m: every checked point of the "
                   "arm stays above it by --table-clearance")
      ->group(group);
  command
      ->add_option("--table-clearance", flags->table_clearance,
                   fmt::format("clearance kept above the bench, m (default {})",
                               kinematics::SafetyEnvelope{}.table_clearance_m))
      ->group(group);
  command
      ->add_option("--keep-out", flags->keep_out,
                   "keep-out cylinder, e.g. the turntable: x y radius z_min z_max (base frame, m)")
      ->expected(5)
      ->group(group);
}

void ApplyEnvelopeFlags(const EnvelopeFlags& flags, kinematics::SafetyEnvelope* envelope) {
  envelope->table_z_base_m = flags.table_z;
  envelope->table_clearance_m =
      flags.table_clearance.value_or(kinematics::SafetyEnvelope{}.table_clearance_m);
  if (flags.keep_out.size() == 5) {
    envelope->keep_out =
        kinematics::KeepOutCylinder{Eigen::Vector2d(flags.keep_out[0], flags.keep_out[1]),
                                    flags.keep_out[2], flags.keep_out[3], flags.keep_out[4]};
  }
  if (const std::string problem = envelope->Validate(); !problem.empty()) {
    throw CLI::ValidationError("safety envelope", problem);
  }
}

std::vector<config::Assignment> EnvelopeSettings(const EnvelopeFlags& flags) {
  std::vector<config::Assignment> settings;
  if (flags.table_z) {
    settings.push_back({"envelope.table_z", fmt::format("{}", *flags.table_z), "--table-z"});
  }
  if (flags.table_clearance) {
    settings.push_back({"envelope.table_clearance", fmt::format("{}", *flags.table_clearance),
                        "--table-clearance"});
  }
  if (flags.keep_out.size() == 5) {
    settings.push_back(
        {"envelope.keep_out", fmt::format("{}", fmt::join(flags.keep_out, " ")), "--keep-out"});
  }
  return settings;
}

std::optional<kinematics::SafetyEnvelope> DriverEnvelopeOf(const EnvelopeFlags& flags) {
  if (!flags.table_z && flags.keep_out.empty()) return std::nullopt;
  kinematics::SafetyEnvelope driver;
  ApplyEnvelopeFlags(flags, &driver);
  return driver;
}

std::optional<kinematics::SafetyEnvelope> PlanningEnvelopeOf(const EnvelopeFlags& flags) {
  const std::optional<kinematics::SafetyEnvelope> driver = DriverEnvelopeOf(flags);
  if (!driver) return std::nullopt;
  return kinematics::PlanningEnvelope(*driver);
}

}  // namespace avc::cli
