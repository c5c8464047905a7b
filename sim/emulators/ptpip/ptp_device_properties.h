#pragma once

// The exposure properties the emulated camera offers, with enumerated choices like a real body in
// manual mode: ExposureIndex (ISO), ExposureTime (1/10000 s units), FNumber (1/100 units) and
// CompressionSetting (image quality). Set() answers with the PTP response code a camera would.

#include <cstdint>
#include <map>
#include <vector>

#include "sim/emulators/ptpip/emulated_capture.h"
#include "sim/emulators/ptpip/ptp_datasets.h"

namespace avc::sim::ptp {

class DeviceProperties {
 public:
  DeviceProperties();

  std::vector<uint16_t> Codes() const;
  // nullptr when the camera does not have the property.
  const DevicePropDesc* Find(uint16_t code) const;
  // kRcOk, kRcDevicePropNotSupported, kRcAccessDenied (read-only) or kRcInvalidDevicePropValue.
  uint16_t Set(uint16_t code, uint32_t value);
  EmulatedSettings Settings() const;

 private:
  std::map<uint16_t, DevicePropDesc> properties_;
};

}  // namespace avc::sim::ptp
