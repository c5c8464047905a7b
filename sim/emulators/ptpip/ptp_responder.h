#pragma once

// The PTP side of the emulated camera, free of sockets: one operation request (plus the data the
// initiator sent, if any) in, the response code, parameters and data for the initiator out.
// The transport (PtpIpCamera) runs the capture itself when a result says so, because that part
// waits on the clock and calls the frame source.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/emulators/ptpip/ptp_datasets.h"
#include "sim/emulators/ptpip/ptp_device_properties.h"
#include "sim/emulators/ptpip/ptp_object_store.h"
#include "sim/emulators/ptpip/ptpip_packets.h"

namespace avc::sim::ptp {

struct DeviceIdentity {
  std::string manufacturer = "AVC";
  std::string model = "AVC PTP/IP camera emulator";
  std::string device_version = "1.0";
  std::string serial_number = "0000000001";
};

struct PtpResult {
  uint16_t code = kRcOk;
  std::vector<uint32_t> params;
  std::optional<std::vector<uint8_t>> data;  // data phase to the initiator, before the response
  bool start_capture = false;                // an accepted InitiateCapture
};

class PtpResponder {
 public:
  explicit PtpResponder(DeviceIdentity identity);

  // Operations whose data phase runs from the initiator to us (SetDevicePropValue).
  static bool ExpectsDataFromInitiator(uint16_t code);
  // The operation codes Handle() implements (what GetDeviceInfo advertises).
  static std::vector<uint16_t> SupportedOperations();

  PtpResult Handle(const OperationRequest& request, const std::vector<uint8_t>& data_in);

  // The next `count` InitiateCapture requests answer DeviceBusy.
  void InjectBusy(int count) { busy_left_ = count; }
  // The connection went away: the session ends (the card keeps its images).
  void EndSession() { session_open_ = false; }

  DeviceInfo Info() const;
  EmulatedSettings settings() const { return properties_.Settings(); }
  ObjectStore& store() { return store_; }
  const ObjectStore& store() const { return store_; }
  bool session_open() const { return session_open_; }
  int64_t sessions_opened() const { return sessions_opened_; }

 private:
  PtpResult GetStorageInfo(const OperationRequest& request) const;
  PtpResult GetObjectHandles(const OperationRequest& request) const;
  PtpResult GetObjectInfo(const OperationRequest& request) const;
  PtpResult GetObject(const OperationRequest& request) const;
  PtpResult GetPartialObject(const OperationRequest& request) const;
  PtpResult DeleteObject(const OperationRequest& request);
  PtpResult InitiateCapture(const OperationRequest& request);
  PtpResult GetDevicePropDesc(const OperationRequest& request) const;
  PtpResult GetDevicePropValue(const OperationRequest& request) const;
  PtpResult SetDevicePropValue(const OperationRequest& request,
                               const std::vector<uint8_t>& data_in);

  DeviceIdentity identity_;
  DeviceProperties properties_;
  ObjectStore store_;
  bool session_open_ = false;
  int64_t sessions_opened_ = 0;
  int busy_left_ = 0;
};

}  // namespace avc::sim::ptp
