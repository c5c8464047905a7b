// calibration.yaml text read back into a CellCalibration (calibration::CalibrationFromYaml), as
// `avc scan` and the calibrator load it.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/calibration/cell/calibration_yaml.h"

#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    avc::calibration::CalibrationFromYaml(std::string(avc::fuzz::AsText(data, size)),
                                          "calibration.yaml");
  } catch (const std::runtime_error&) {  // names the file, line and field at fault
  }
  return 0;
}
