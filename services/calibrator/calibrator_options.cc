#include "services/calibrator/calibrator_options.h"

namespace avc::calibrator {

const config::OptionTable<CalibratorNodeOptions>& CalibratorOptionTable() {
  static const config::OptionTable<CalibratorNodeOptions> table = [] {
    config::OptionTable<CalibratorNodeOptions> made("calibrator");
    made.Add("camera_id", [](auto& o) -> auto& { return o.camera_id; },
             {"", "camera id stamped on the cameras it publishes"})
        .Add("republish_period", [](auto& o) -> auto& { return o.republish_period; },
             {"ms", "CALIBRATION is published again this often", 100, 3600000});
    return made;
  }();
  return table;
}

}  // namespace avc::calibrator
