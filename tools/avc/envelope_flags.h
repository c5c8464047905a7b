#pragma once

// The fixed safety-envelope flags (--table-z, --table-clearance, --keep-out): avc robot enforces
// them on every motion; avc scan gives the same numbers to the planner, so that it only chooses
// views whose moves the driver will make.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/config/option_text.h"
#include "core/kinematics/safety_envelope.h"

namespace avc::cli {

struct EnvelopeFlags {
  std::optional<double> table_z;
  std::optional<double> table_clearance;  // default: SafetyEnvelope's
  std::vector<double> keep_out;           // x y radius z_min z_max, or empty
};

void AddEnvelopeFlags(CLI::App* command, EnvelopeFlags* flags);

// Sets envelope's table plane and keep-out cylinder from the flags (unset flags leave them
// unset). Throws CLI::ValidationError when the result is not a usable envelope.
void ApplyEnvelopeFlags(const EnvelopeFlags& flags, kinematics::SafetyEnvelope* envelope);

// The flags given as avc-robot's options (envelope.table_z, ...; drivers/robot/robot_options.h).
std::vector<config::Assignment> EnvelopeSettings(const EnvelopeFlags& flags);

// The flags' envelope as avc robot enforces it, or none when neither --table-z nor --keep-out
// is given.
std::optional<kinematics::SafetyEnvelope> DriverEnvelopeOf(const EnvelopeFlags& flags);

// For avc calibrate: the flags' envelope as a planner checks it (kinematics::PlanningEnvelope),
// or none when neither --table-z nor --keep-out is given.
std::optional<kinematics::SafetyEnvelope> PlanningEnvelopeOf(const EnvelopeFlags& flags);

}  // namespace avc::cli
