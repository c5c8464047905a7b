#include "sim/emulators/ptpip/ptp_responder.h"

#include <algorithm>

#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim::ptp {
namespace {

constexpr uint32_t kAllStorages = 0xFFFFFFFF;
constexpr uint32_t kRootParent = 0xFFFFFFFF;
constexpr uint32_t kAllObjects = 0xFFFFFFFF;

PtpResult Code(uint16_t code) { return PtpResult{code, {}, std::nullopt, false}; }

PtpResult Data(std::vector<uint8_t> bytes, std::vector<uint32_t> params = {}) {
  return PtpResult{kRcOk, std::move(params), std::move(bytes), false};
}

// Missing parameters read as 0, as PTP initiators may omit trailing zeros.
uint32_t Param(const OperationRequest& request, size_t index) {
  return index < request.params.size() ? request.params[index] : 0;
}

}  // namespace

PtpResponder::PtpResponder(DeviceIdentity identity) : identity_(std::move(identity)) {}

bool PtpResponder::ExpectsDataFromInitiator(uint16_t code) { return code == kOpSetDevicePropValue; }

std::vector<uint16_t> PtpResponder::SupportedOperations() {
  return {kOpGetDeviceInfo,      kOpOpenSession,      kOpCloseSession,      kOpGetStorageIds,
          kOpGetStorageInfo,     kOpGetObjectHandles, kOpGetObjectInfo,     kOpGetObject,
          kOpDeleteObject,       kOpInitiateCapture,  kOpGetDevicePropDesc, kOpGetDevicePropValue,
          kOpSetDevicePropValue, kOpGetPartialObject};
}

DeviceInfo PtpResponder::Info() const {
  DeviceInfo info;
  info.operations = SupportedOperations();
  info.events = {kEventObjectAdded, kEventCaptureComplete};
  info.device_properties = properties_.Codes();
  info.capture_formats = {kFormatExifJpeg, kFormatPng};
  info.image_formats = {kFormatExifJpeg, kFormatPng};
  info.manufacturer = identity_.manufacturer;
  info.model = identity_.model;
  info.device_version = identity_.device_version;
  info.serial_number = identity_.serial_number;
  return info;
}

PtpResult PtpResponder::Handle(const OperationRequest& request,
                               const std::vector<uint8_t>& data_in) {
  switch (request.code) {
    case kOpGetDeviceInfo:
      return Data(Encode(Info()));
    case kOpOpenSession:
      if (session_open_) return Code(kRcSessionAlreadyOpen);
      if (Param(request, 0) == 0) return Code(kRcParameterNotSupported);
      session_open_ = true;
      ++sessions_opened_;
      return Code(kRcOk);
    default:
      break;
  }
  const std::vector<uint16_t> supported = SupportedOperations();
  if (std::find(supported.begin(), supported.end(), request.code) == supported.end()) {
    return Code(kRcOperationNotSupported);
  }
  if (!session_open_) return Code(kRcSessionNotOpen);
  switch (request.code) {
    case kOpCloseSession:
      session_open_ = false;
      return Code(kRcOk);
    case kOpGetStorageIds: {
      ByteWriter w;
      const uint32_t ids[] = {kStorageId};
      w.U32Array(ids);
      return Data(w.Take());
    }
    case kOpGetStorageInfo:
      return GetStorageInfo(request);
    case kOpGetObjectHandles:
      return GetObjectHandles(request);
    case kOpGetObjectInfo:
      return GetObjectInfo(request);
    case kOpGetObject:
      return GetObject(request);
    case kOpGetPartialObject:
      return GetPartialObject(request);
    case kOpDeleteObject:
      return DeleteObject(request);
    case kOpInitiateCapture:
      return InitiateCapture(request);
    case kOpGetDevicePropDesc:
      return GetDevicePropDesc(request);
    case kOpGetDevicePropValue:
      return GetDevicePropValue(request);
    case kOpSetDevicePropValue:
      return SetDevicePropValue(request, data_in);
    default:
      return Code(kRcOperationNotSupported);
  }
}

PtpResult PtpResponder::GetStorageInfo(const OperationRequest& request) const {
  if (Param(request, 0) != kStorageId) return Code(kRcInvalidStorageId);
  return Data(Encode(store_.Info()));
}

PtpResult PtpResponder::GetObjectHandles(const OperationRequest& request) const {
  const uint32_t storage = Param(request, 0);
  const uint32_t format = Param(request, 1);
  const uint32_t parent = Param(request, 2);
  if (storage != kAllStorages && storage != kStorageId) return Code(kRcInvalidStorageId);
  std::vector<uint32_t> handles;
  // Everything lives in the root, so "all objects" (0) and "root" (0xFFFFFFFF) agree; an image
  // has no children.
  if (parent != 0 && parent != kRootParent) {
    if (store_.Find(parent) == nullptr) return Code(kRcInvalidParentObject);
  } else {
    for (uint32_t handle : store_.Handles()) {
      if (format == 0 || store_.Find(handle)->info.object_format == format) {
        handles.push_back(handle);
      }
    }
  }
  ByteWriter w;
  w.U32Array(handles);
  return Data(w.Take());
}

PtpResult PtpResponder::GetObjectInfo(const OperationRequest& request) const {
  const StoredObject* object = store_.Find(Param(request, 0));
  if (object == nullptr) return Code(kRcInvalidObjectHandle);
  return Data(Encode(object->info));
}

PtpResult PtpResponder::GetObject(const OperationRequest& request) const {
  const StoredObject* object = store_.Find(Param(request, 0));
  if (object == nullptr) return Code(kRcInvalidObjectHandle);
  return Data(object->data);
}

PtpResult PtpResponder::GetPartialObject(const OperationRequest& request) const {
  const StoredObject* object = store_.Find(Param(request, 0));
  if (object == nullptr) return Code(kRcInvalidObjectHandle);
  const uint64_t offset = Param(request, 1);
  const uint64_t max_bytes = Param(request, 2);
  if (offset > object->data.size()) return Code(kRcParameterNotSupported);
  const uint64_t count = std::min<uint64_t>(max_bytes, object->data.size() - offset);
  const auto begin = object->data.begin() + static_cast<ptrdiff_t>(offset);
  return Data(std::vector<uint8_t>(begin, begin + static_cast<ptrdiff_t>(count)),
              {static_cast<uint32_t>(count)});
}

PtpResult PtpResponder::DeleteObject(const OperationRequest& request) {
  const uint32_t handle = Param(request, 0);
  if (handle == kAllObjects) {
    store_.Clear();
    return Code(kRcOk);
  }
  return Code(store_.Remove(handle) ? kRcOk : kRcInvalidObjectHandle);
}

PtpResult PtpResponder::InitiateCapture(const OperationRequest& request) {
  const uint32_t storage = Param(request, 0);
  if (storage != 0 && storage != kStorageId) return Code(kRcInvalidStorageId);
  if (busy_left_ > 0) {
    --busy_left_;
    return Code(kRcDeviceBusy);
  }
  PtpResult result = Code(kRcOk);
  result.start_capture = true;
  return result;
}

PtpResult PtpResponder::GetDevicePropDesc(const OperationRequest& request) const {
  const DevicePropDesc* desc = properties_.Find(static_cast<uint16_t>(Param(request, 0)));
  if (desc == nullptr) return Code(kRcDevicePropNotSupported);
  return Data(Encode(*desc));
}

PtpResult PtpResponder::GetDevicePropValue(const OperationRequest& request) const {
  const DevicePropDesc* desc = properties_.Find(static_cast<uint16_t>(Param(request, 0)));
  if (desc == nullptr) return Code(kRcDevicePropNotSupported);
  return Data(EncodePropValue(desc->data_type, desc->current));
}

PtpResult PtpResponder::SetDevicePropValue(const OperationRequest& request,
                                           const std::vector<uint8_t>& data_in) {
  const auto code = static_cast<uint16_t>(Param(request, 0));
  const DevicePropDesc* desc = properties_.Find(code);
  if (desc == nullptr) return Code(kRcDevicePropNotSupported);
  uint32_t value = 0;
  try {
    value = DecodePropValue(desc->data_type, data_in);
  } catch (const PtpDecodeError&) {
    return Code(kRcInvalidDevicePropFormat);
  }
  return Code(properties_.Set(code, value));
}

}  // namespace avc::sim::ptp
