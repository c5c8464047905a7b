#pragma once

// avc-calibrator's options, declared once for --config, --set, the configuration it publishes
// and --help (core/config/option_table.h). The calibration itself is its file (and CALIBRATION).

#include "core/config/option_table.h"
#include "services/calibrator/calibrator_node.h"

namespace avc::calibrator {

const config::OptionTable<CalibratorNodeOptions>& CalibratorOptionTable();

}  // namespace avc::calibrator
