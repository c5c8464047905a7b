#pragma once

// The arm's fixed safety envelope (SafetyEnvelope's bench plane and keep-out cylinder) declared
// once for every option table that holds it: avc-robot enforces it on every motion, avc scan
// gives the same numbers to the planner so that it only chooses views the driver will make.

#include <stdexcept>
#include <string>
#include <string_view>

#include "core/config/option_table.h"
#include "core/kinematics/keep_out.h"
#include "core/kinematics/safety_envelope.h"

namespace avc::kinematics {

// Adds PREFIX.table_z, PREFIX.table_clearance and PREFIX.keep_out to `table`; `envelope` is a
// generic lambda returning the SafetyEnvelope inside Options.
template <typename Options, typename Access>
void AddFixedEnvelopeOptions(config::OptionTable<Options>& table, const std::string& prefix,
                             Access envelope) {
  table
      .Add(prefix + ".table_z", [envelope](auto& o) -> auto& { return envelope(o).table_z_base_m; },
           {"m",
            "the bench's height in the base frame; every checked point stays above it "
            "(none: no bench)",
            -10, 10})
      .Add(prefix + ".table_clearance",
           [envelope](auto& o) -> auto& { return envelope(o).table_clearance_m; },
           {"m", "clearance kept above the bench", 0, 10})
      .AddText(
          prefix + ".keep_out",
          [envelope](const Options& o) {
            const auto& keep_out = envelope(o).keep_out;
            return keep_out ? KeepOutText(*keep_out) : std::string(config::kNone);
          },
          [envelope](Options& o, std::string_view text) {
            auto& keep_out = envelope(o).keep_out;
            if (text == config::kNone) {
              keep_out.reset();
              return;
            }
            keep_out = ParseKeepOut(std::string(text));
            if (!keep_out) {
              throw std::invalid_argument("not five numbers (x y radius z_min z_max) or none");
            }
          },
          {"m",
           "keep-out cylinder, e.g. the turntable: \"x y radius z_min z_max\" in the base "
           "frame, or none"});
}

}  // namespace avc::kinematics
