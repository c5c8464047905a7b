#pragma once

// PTP (ISO 15740 / PIMA 15740:2000) and PTP/IP (CIPA DC-005) numbers the emulator and its tests
// use. All multi-byte fields on the wire are little-endian.

#include <cstdint>

namespace avc::sim::ptp {

// Operation codes.
inline constexpr uint16_t kOpGetDeviceInfo = 0x1001;
inline constexpr uint16_t kOpOpenSession = 0x1002;
inline constexpr uint16_t kOpCloseSession = 0x1003;
inline constexpr uint16_t kOpGetStorageIds = 0x1004;
inline constexpr uint16_t kOpGetStorageInfo = 0x1005;
inline constexpr uint16_t kOpGetObjectHandles = 0x1007;
inline constexpr uint16_t kOpGetObjectInfo = 0x1008;
inline constexpr uint16_t kOpGetObject = 0x1009;
inline constexpr uint16_t kOpDeleteObject = 0x100B;
inline constexpr uint16_t kOpInitiateCapture = 0x100E;
inline constexpr uint16_t kOpGetDevicePropDesc = 0x1014;
inline constexpr uint16_t kOpGetDevicePropValue = 0x1015;
inline constexpr uint16_t kOpSetDevicePropValue = 0x1016;
inline constexpr uint16_t kOpGetPartialObject = 0x101B;

// Response codes.
inline constexpr uint16_t kRcOk = 0x2001;
inline constexpr uint16_t kRcGeneralError = 0x2002;
inline constexpr uint16_t kRcSessionNotOpen = 0x2003;
inline constexpr uint16_t kRcOperationNotSupported = 0x2005;
inline constexpr uint16_t kRcParameterNotSupported = 0x2006;
inline constexpr uint16_t kRcInvalidStorageId = 0x2008;
inline constexpr uint16_t kRcInvalidObjectHandle = 0x2009;
inline constexpr uint16_t kRcDevicePropNotSupported = 0x200A;
inline constexpr uint16_t kRcAccessDenied = 0x200F;
inline constexpr uint16_t kRcDeviceBusy = 0x2019;
inline constexpr uint16_t kRcInvalidParentObject = 0x201A;
inline constexpr uint16_t kRcInvalidDevicePropFormat = 0x201B;
inline constexpr uint16_t kRcInvalidDevicePropValue = 0x201C;
inline constexpr uint16_t kRcSessionAlreadyOpen = 0x201E;

// Event codes.
inline constexpr uint16_t kEventObjectAdded = 0x4002;
inline constexpr uint16_t kEventCaptureComplete = 0x400D;

// Device property codes.
inline constexpr uint16_t kPropCompressionSetting = 0x5004;
inline constexpr uint16_t kPropFNumber = 0x5007;
inline constexpr uint16_t kPropExposureTime = 0x500D;
inline constexpr uint16_t kPropExposureIndex = 0x500F;

// Data type codes (DevicePropDesc).
inline constexpr uint16_t kTypeUint8 = 0x0002;
inline constexpr uint16_t kTypeUint16 = 0x0004;
inline constexpr uint16_t kTypeUint32 = 0x0006;

// Object format codes.
inline constexpr uint16_t kFormatUndefined = 0x3000;
inline constexpr uint16_t kFormatExifJpeg = 0x3801;
inline constexpr uint16_t kFormatPng = 0x380B;

// Storage.
inline constexpr uint16_t kStorageRemovableRam = 0x0004;
inline constexpr uint16_t kFilesystemGenericHierarchical = 0x0002;
inline constexpr uint16_t kAccessReadWrite = 0x0000;

// DevicePropDesc GetSet and FormFlag.
inline constexpr uint8_t kPropGet = 0x00;
inline constexpr uint8_t kPropGetSet = 0x01;
inline constexpr uint8_t kFormNone = 0x00;
inline constexpr uint8_t kFormRange = 0x01;
inline constexpr uint8_t kFormEnumeration = 0x02;

// PTP/IP "data phase" field of an operation request: 2 = the initiator sends data.
inline constexpr uint32_t kDataPhaseNoneOrIn = 1;
inline constexpr uint32_t kDataPhaseOut = 2;

// PTP/IP version 1.0 as sent on the wire (minor in the low half).
inline constexpr uint32_t kPtpIpVersion = 0x00010000;

}  // namespace avc::sim::ptp
