#pragma once

// avc scan's options, declared once (core/config/option_table.h) for its --config, --set, flags
// and --help, and kept with each scan as config/avc-scan.toml:
//   scan.*      how long the scan waits for services and stages
//   capture.*   how views are captured, and the masks the planner gets (masks.*)
//   planner.*   Algorithm 1's settings for avc-planner's plan jobs (none: the planner's own)
//   envelope.*  the arm's fixed safety envelope as avc robot enforces it, given to the planner
//               so that it only chooses views the driver will make

#include <string>

#include "core/config/option_table.h"
#include "core/kinematics/safety_envelope.h"
#include "orchestrator/scan_run.h"

namespace avc::orchestrator {

struct ScanOptions {
  ScanRunOptions run;
  kinematics::SafetyEnvelope envelope;  // unused when neither table_z nor keep_out is set

  // The run's options with the envelope added to the planner's settings: what RunScan takes.
  ScanRunOptions RunOptions() const;
};

const config::OptionTable<ScanOptions>& ScanOptionTable();

}  // namespace avc::orchestrator
