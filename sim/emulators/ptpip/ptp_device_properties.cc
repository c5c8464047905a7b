#include "sim/emulators/ptpip/ptp_device_properties.h"

#include <algorithm>

#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim::ptp {
namespace {

DevicePropDesc Enumerated(uint16_t code, uint16_t data_type, uint32_t current,
                          std::vector<uint32_t> choices) {
  DevicePropDesc d;
  d.code = code;
  d.data_type = data_type;
  d.get_set = kPropGetSet;
  d.factory_default = current;
  d.current = current;
  d.form_flag = kFormEnumeration;
  d.enumeration = std::move(choices);
  return d;
}

}  // namespace

DeviceProperties::DeviceProperties() {
  properties_[kPropExposureIndex] =
      Enumerated(kPropExposureIndex, kTypeUint16, 100, {100, 200, 400, 800, 1600, 3200, 6400});
  // 1/1000 s ... 1 s in the camera's third-stop-free full stops.
  properties_[kPropExposureTime] = Enumerated(
      kPropExposureTime, kTypeUint32, 80, {10, 20, 40, 80, 166, 333, 666, 1250, 2500, 5000, 10000});
  properties_[kPropFNumber] =
      Enumerated(kPropFNumber, kTypeUint16, 800, {350, 400, 560, 800, 1100, 1600, 2200});
  // PTP leaves the values vendor-defined; 1..3 = basic, normal, fine.
  properties_[kPropCompressionSetting] =
      Enumerated(kPropCompressionSetting, kTypeUint8, 3, {1, 2, 3});
}

std::vector<uint16_t> DeviceProperties::Codes() const {
  std::vector<uint16_t> codes;
  for (const auto& [code, desc] : properties_) codes.push_back(code);
  return codes;
}

const DevicePropDesc* DeviceProperties::Find(uint16_t code) const {
  const auto it = properties_.find(code);
  return it == properties_.end() ? nullptr : &it->second;
}

uint16_t DeviceProperties::Set(uint16_t code, uint32_t value) {
  const auto it = properties_.find(code);
  if (it == properties_.end()) return kRcDevicePropNotSupported;
  DevicePropDesc& desc = it->second;
  if (desc.get_set != kPropGetSet) return kRcAccessDenied;
  if (desc.form_flag == kFormEnumeration &&
      std::find(desc.enumeration.begin(), desc.enumeration.end(), value) ==
          desc.enumeration.end()) {
    return kRcInvalidDevicePropValue;
  }
  desc.current = value;
  return kRcOk;
}

EmulatedSettings DeviceProperties::Settings() const {
  EmulatedSettings s;
  s.iso = properties_.at(kPropExposureIndex).current;
  s.shutter_s = properties_.at(kPropExposureTime).current / 10000.0;
  s.f_number = properties_.at(kPropFNumber).current / 100.0;
  return s;
}

}  // namespace avc::sim::ptp
