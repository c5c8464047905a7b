#pragma once

// PTP datasets (PIMA 15740 chapter 5) the emulator sends in data phases: DeviceInfo, StorageInfo,
// ObjectInfo and DevicePropDesc, with decoders so tests and tools can read them back.
// Property values are integers (UINT8/16/32 and their signed twins), which is all the emulated
// exposure properties need; other data types are refused with a clear error.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace avc::sim::ptp {

struct DeviceInfo {
  uint16_t standard_version = 100;
  uint32_t vendor_extension_id = 0;
  uint16_t vendor_extension_version = 0;
  std::string vendor_extension_desc;
  uint16_t functional_mode = 0;
  std::vector<uint16_t> operations;
  std::vector<uint16_t> events;
  std::vector<uint16_t> device_properties;
  std::vector<uint16_t> capture_formats;
  std::vector<uint16_t> image_formats;
  std::string manufacturer;
  std::string model;
  std::string device_version;
  std::string serial_number;
};

struct StorageInfo {
  uint16_t storage_type = 0;
  uint16_t filesystem_type = 0;
  uint16_t access_capability = 0;
  uint64_t max_capacity = 0;
  uint64_t free_space_bytes = 0;
  uint32_t free_space_images = 0;
  std::string description;
  std::string volume_label;
};

struct ObjectInfo {
  uint32_t storage_id = 0;
  uint16_t object_format = 0;
  uint16_t protection_status = 0;
  uint32_t compressed_size = 0;
  uint16_t thumb_format = 0;
  uint32_t thumb_compressed_size = 0;
  uint32_t thumb_width = 0;
  uint32_t thumb_height = 0;
  uint32_t image_width = 0;
  uint32_t image_height = 0;
  uint32_t image_bit_depth = 0;
  uint32_t parent_object = 0;
  uint16_t association_type = 0;
  uint32_t association_desc = 0;
  uint32_t sequence_number = 0;
  std::string filename;
  std::string capture_date;  // "YYYYMMDDThhmmss"
  std::string modification_date;
  std::string keywords;
};

struct DevicePropDesc {
  uint16_t code = 0;
  uint16_t data_type = 0;
  uint8_t get_set = 0;
  uint32_t factory_default = 0;
  uint32_t current = 0;
  uint8_t form_flag = 0;
  std::vector<uint32_t> enumeration;  // form_flag == enumeration
  uint32_t range_min = 0;             // form_flag == range
  uint32_t range_max = 0;
  uint32_t range_step = 0;
};

// Bytes of one value of an integer data type; throws std::invalid_argument for other types.
size_t IntegerTypeBytes(uint16_t data_type);
std::vector<uint8_t> EncodePropValue(uint16_t data_type, uint32_t value);
// Throws PtpDecodeError when the bytes do not hold exactly one value of the type.
uint32_t DecodePropValue(uint16_t data_type, std::span<const uint8_t> bytes);

std::vector<uint8_t> Encode(const DeviceInfo& d);
std::vector<uint8_t> Encode(const StorageInfo& d);
std::vector<uint8_t> Encode(const ObjectInfo& d);
std::vector<uint8_t> Encode(const DevicePropDesc& d);

DeviceInfo DecodeDeviceInfo(std::span<const uint8_t> bytes);
StorageInfo DecodeStorageInfo(std::span<const uint8_t> bytes);
ObjectInfo DecodeObjectInfo(std::span<const uint8_t> bytes);
DevicePropDesc DecodeDevicePropDesc(std::span<const uint8_t> bytes);

}  // namespace avc::sim::ptp
