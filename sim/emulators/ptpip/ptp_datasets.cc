#include "sim/emulators/ptpip/ptp_datasets.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim::ptp {
namespace {

// Signed types have the unsigned code minus one (INT8 0x0001, UINT8 0x0002, ...).
uint16_t UnsignedType(uint16_t data_type) {
  return (data_type >= 0x0001 && data_type <= 0x0006 && data_type % 2 == 1) ? data_type + 1
                                                                            : data_type;
}

void WriteValue(ByteWriter& w, uint16_t data_type, uint32_t value) {
  switch (IntegerTypeBytes(data_type)) {
    case 1:
      w.U8(static_cast<uint8_t>(value));
      break;
    case 2:
      w.U16(static_cast<uint16_t>(value));
      break;
    default:
      w.U32(value);
      break;
  }
}

uint32_t ReadValue(ByteReader& r, uint16_t data_type, std::string_view field) {
  switch (IntegerTypeBytes(data_type)) {
    case 1:
      return r.U8(field);
    case 2:
      return r.U16(field);
    default:
      return r.U32(field);
  }
}

}  // namespace

size_t IntegerTypeBytes(uint16_t data_type) {
  switch (UnsignedType(data_type)) {
    case kTypeUint8:
      return 1;
    case kTypeUint16:
      return 2;
    case kTypeUint32:
      return 4;
    default:
      throw std::invalid_argument(
          fmt::format("PTP data type 0x{:04x} is not an 8, 16 or 32 bit integer", data_type));
  }
}

std::vector<uint8_t> EncodePropValue(uint16_t data_type, uint32_t value) {
  ByteWriter w;
  WriteValue(w, data_type, value);
  return w.Take();
}

uint32_t DecodePropValue(uint16_t data_type, std::span<const uint8_t> bytes) {
  size_t width = 0;
  try {
    width = IntegerTypeBytes(data_type);
  } catch (const std::invalid_argument& e) {
    throw PtpDecodeError(fmt::format("PTP property value: {}", e.what()));
  }
  if (bytes.size() != width) {
    throw PtpDecodeError(fmt::format("PTP property value of type 0x{:04x}: {} bytes, expected {}",
                                     data_type, bytes.size(), width));
  }
  ByteReader r(bytes, "PTP property value");
  return ReadValue(r, data_type, "value");
}

std::vector<uint8_t> Encode(const DeviceInfo& d) {
  ByteWriter w;
  w.U16(d.standard_version);
  w.U32(d.vendor_extension_id);
  w.U16(d.vendor_extension_version);
  w.PtpString(d.vendor_extension_desc);
  w.U16(d.functional_mode);
  w.U16Array(d.operations);
  w.U16Array(d.events);
  w.U16Array(d.device_properties);
  w.U16Array(d.capture_formats);
  w.U16Array(d.image_formats);
  w.PtpString(d.manufacturer);
  w.PtpString(d.model);
  w.PtpString(d.device_version);
  w.PtpString(d.serial_number);
  return w.Take();
}

std::vector<uint8_t> Encode(const StorageInfo& d) {
  ByteWriter w;
  w.U16(d.storage_type);
  w.U16(d.filesystem_type);
  w.U16(d.access_capability);
  w.U64(d.max_capacity);
  w.U64(d.free_space_bytes);
  w.U32(d.free_space_images);
  w.PtpString(d.description);
  w.PtpString(d.volume_label);
  return w.Take();
}

std::vector<uint8_t> Encode(const ObjectInfo& d) {
  ByteWriter w;
  w.U32(d.storage_id);
  w.U16(d.object_format);
  w.U16(d.protection_status);
  w.U32(d.compressed_size);
  w.U16(d.thumb_format);
  w.U32(d.thumb_compressed_size);
  w.U32(d.thumb_width);
  w.U32(d.thumb_height);
  w.U32(d.image_width);
  w.U32(d.image_height);
  w.U32(d.image_bit_depth);
  w.U32(d.parent_object);
  w.U16(d.association_type);
  w.U32(d.association_desc);
  w.U32(d.sequence_number);
  w.PtpString(d.filename);
  w.PtpString(d.capture_date);
  w.PtpString(d.modification_date);
  w.PtpString(d.keywords);
  return w.Take();
}

std::vector<uint8_t> Encode(const DevicePropDesc& d) {
  ByteWriter w;
  w.U16(d.code);
  w.U16(d.data_type);
  w.U8(d.get_set);
  WriteValue(w, d.data_type, d.factory_default);
  WriteValue(w, d.data_type, d.current);
  w.U8(d.form_flag);
  if (d.form_flag == kFormEnumeration) {
    if (d.enumeration.size() > 0xFFFF) {
      throw std::invalid_argument(fmt::format("PTP property 0x{:04x}: {} enumeration values",
                                              d.code, d.enumeration.size()));
    }
    w.U16(static_cast<uint16_t>(d.enumeration.size()));
    for (uint32_t v : d.enumeration) WriteValue(w, d.data_type, v);
  } else if (d.form_flag == kFormRange) {
    WriteValue(w, d.data_type, d.range_min);
    WriteValue(w, d.data_type, d.range_max);
    WriteValue(w, d.data_type, d.range_step);
  }
  return w.Take();
}

DeviceInfo DecodeDeviceInfo(std::span<const uint8_t> bytes) {
  ByteReader r(bytes, "PTP DeviceInfo");
  DeviceInfo d;
  d.standard_version = r.U16("standard version");
  d.vendor_extension_id = r.U32("vendor extension id");
  d.vendor_extension_version = r.U16("vendor extension version");
  d.vendor_extension_desc = r.PtpString("vendor extension description");
  d.functional_mode = r.U16("functional mode");
  d.operations = r.U16Array("operations supported");
  d.events = r.U16Array("events supported");
  d.device_properties = r.U16Array("device properties supported");
  d.capture_formats = r.U16Array("capture formats");
  d.image_formats = r.U16Array("image formats");
  d.manufacturer = r.PtpString("manufacturer");
  d.model = r.PtpString("model");
  d.device_version = r.PtpString("device version");
  d.serial_number = r.PtpString("serial number");
  r.ExpectEnd();
  return d;
}

StorageInfo DecodeStorageInfo(std::span<const uint8_t> bytes) {
  ByteReader r(bytes, "PTP StorageInfo");
  StorageInfo d;
  d.storage_type = r.U16("storage type");
  d.filesystem_type = r.U16("filesystem type");
  d.access_capability = r.U16("access capability");
  d.max_capacity = r.U64("max capacity");
  d.free_space_bytes = r.U64("free space in bytes");
  d.free_space_images = r.U32("free space in images");
  d.description = r.PtpString("storage description");
  d.volume_label = r.PtpString("volume label");
  r.ExpectEnd();
  return d;
}

ObjectInfo DecodeObjectInfo(std::span<const uint8_t> bytes) {
  ByteReader r(bytes, "PTP ObjectInfo");
  ObjectInfo d;
  d.storage_id = r.U32("storage id");
  d.object_format = r.U16("object format");
  d.protection_status = r.U16("protection status");
  d.compressed_size = r.U32("object compressed size");
  d.thumb_format = r.U16("thumb format");
  d.thumb_compressed_size = r.U32("thumb compressed size");
  d.thumb_width = r.U32("thumb width");
  d.thumb_height = r.U32("thumb height");
  d.image_width = r.U32("image width");
  d.image_height = r.U32("image height");
  d.image_bit_depth = r.U32("image bit depth");
  d.parent_object = r.U32("parent object");
  d.association_type = r.U16("association type");
  d.association_desc = r.U32("association description");
  d.sequence_number = r.U32("sequence number");
  d.filename = r.PtpString("filename");
  d.capture_date = r.PtpString("capture date");
  d.modification_date = r.PtpString("modification date");
  d.keywords = r.PtpString("keywords");
  r.ExpectEnd();
  return d;
}

DevicePropDesc DecodeDevicePropDesc(std::span<const uint8_t> bytes) {
  ByteReader r(bytes, "PTP DevicePropDesc");
  DevicePropDesc d;
  d.code = r.U16("property code");
  d.data_type = r.U16("data type");
  try {
    IntegerTypeBytes(d.data_type);
  } catch (const std::invalid_argument& e) {
    throw PtpDecodeError(fmt::format("PTP DevicePropDesc 0x{:04x}: {}", d.code, e.what()));
  }
  d.get_set = r.U8("get/set");
  d.factory_default = ReadValue(r, d.data_type, "factory default");
  d.current = ReadValue(r, d.data_type, "current value");
  d.form_flag = r.U8("form flag");
  if (d.form_flag == kFormEnumeration) {
    const uint16_t count = r.U16("enumeration count");
    d.enumeration.reserve(count);
    for (uint16_t i = 0; i < count; ++i) {
      d.enumeration.push_back(ReadValue(r, d.data_type, "enumeration value"));
    }
  } else if (d.form_flag == kFormRange) {
    d.range_min = ReadValue(r, d.data_type, "range minimum");
    d.range_max = ReadValue(r, d.data_type, "range maximum");
    d.range_step = ReadValue(r, d.data_type, "range step");
  } else if (d.form_flag != kFormNone) {
    throw PtpDecodeError(
        fmt::format("PTP DevicePropDesc 0x{:04x}: unknown form flag {}", d.code, d.form_flag));
  }
  r.ExpectEnd();
  return d;
}

}  // namespace avc::sim::ptp
