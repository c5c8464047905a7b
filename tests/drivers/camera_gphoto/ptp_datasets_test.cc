// PTP datasets: DeviceInfo, StorageInfo, ObjectInfo and DevicePropDesc round trips, PTP string
// encoding, and truncated datasets as clean errors.

#include "sim/emulators/ptpip/ptp_datasets.h"

#include <gtest/gtest.h>

#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim::ptp {
namespace {

DeviceInfo SampleDeviceInfo() {
  DeviceInfo d;
  d.vendor_extension_desc = "none";
  d.operations = {kOpGetDeviceInfo, kOpOpenSession, kOpInitiateCapture};
  d.events = {kEventObjectAdded};
  d.device_properties = {kPropExposureIndex};
  d.capture_formats = {kFormatExifJpeg};
  d.image_formats = {kFormatExifJpeg, kFormatPng};
  d.manufacturer = "AVC";
  d.model = "Emulated camera";
  d.device_version = "1.0";
  d.serial_number = "42";
  return d;
}

TEST(PtpDatasets, PtpStringLayout) {
  ByteWriter w;
  w.PtpString("AB");
  EXPECT_EQ(w.bytes(), (std::vector<uint8_t>{3, 'A', 0, 'B', 0, 0, 0}));
  ByteWriter empty;
  empty.PtpString("");
  EXPECT_EQ(empty.bytes(), std::vector<uint8_t>{0});
  ByteWriter accented;
  accented.PtpString("\xC3\xA9");  // U+00E9 in UTF-8
  ByteReader r(accented.bytes(), "test");
  EXPECT_EQ(r.PtpString("s"), "\xC3\xA9");
  EXPECT_THROW(ByteWriter().PtpString(std::string(255, 'x')), std::invalid_argument);
}

TEST(PtpDatasets, DeviceInfoRoundTrip) {
  const DeviceInfo in = SampleDeviceInfo();
  const DeviceInfo out = DecodeDeviceInfo(Encode(in));
  EXPECT_EQ(out.standard_version, 100);
  EXPECT_EQ(out.vendor_extension_desc, "none");
  EXPECT_EQ(out.operations, in.operations);
  EXPECT_EQ(out.events, in.events);
  EXPECT_EQ(out.device_properties, in.device_properties);
  EXPECT_EQ(out.capture_formats, in.capture_formats);
  EXPECT_EQ(out.image_formats, in.image_formats);
  EXPECT_EQ(out.manufacturer, "AVC");
  EXPECT_EQ(out.model, "Emulated camera");
  EXPECT_EQ(out.device_version, "1.0");
  EXPECT_EQ(out.serial_number, "42");
}

TEST(PtpDatasets, StorageAndObjectInfoRoundTrip) {
  StorageInfo storage;
  storage.storage_type = kStorageRemovableRam;
  storage.max_capacity = 1ull << 35;
  storage.free_space_bytes = (1ull << 35) - 5;
  storage.free_space_images = 0xFFFFFFFF;
  storage.description = "card";
  const StorageInfo storage_out = DecodeStorageInfo(Encode(storage));
  EXPECT_EQ(storage_out.max_capacity, storage.max_capacity);
  EXPECT_EQ(storage_out.free_space_bytes, storage.free_space_bytes);
  EXPECT_EQ(storage_out.description, "card");

  ObjectInfo object;
  object.storage_id = 0x00010001;
  object.object_format = kFormatPng;
  object.compressed_size = 123456;
  object.image_width = 5184;
  object.image_height = 3456;
  object.parent_object = 0;
  object.filename = "IMG_0001.PNG";
  object.capture_date = "20260101T120000";
  const ObjectInfo object_out = DecodeObjectInfo(Encode(object));
  EXPECT_EQ(object_out.storage_id, object.storage_id);
  EXPECT_EQ(object_out.object_format, kFormatPng);
  EXPECT_EQ(object_out.compressed_size, 123456u);
  EXPECT_EQ(object_out.image_width, 5184u);
  EXPECT_EQ(object_out.image_height, 3456u);
  EXPECT_EQ(object_out.filename, "IMG_0001.PNG");
  EXPECT_EQ(object_out.capture_date, "20260101T120000");
}

TEST(PtpDatasets, DevicePropDescRoundTripPerType) {
  DevicePropDesc iso{kPropExposureIndex, kTypeUint16,     kPropGetSet, 100, 400,
                     kFormEnumeration,   {100, 400, 6400}};
  const DevicePropDesc iso_out = DecodeDevicePropDesc(Encode(iso));
  EXPECT_EQ(iso_out.code, kPropExposureIndex);
  EXPECT_EQ(iso_out.current, 400u);
  EXPECT_EQ(iso_out.enumeration, iso.enumeration);
  // code 2 + type 2 + getset 1 + 2 values * 2 + form 1 + count 2 + 3 * 2
  EXPECT_EQ(Encode(iso).size(), 18u);

  DevicePropDesc range;
  range.code = kPropExposureTime;
  range.data_type = kTypeUint32;
  range.current = 80;
  range.form_flag = kFormRange;
  range.range_min = 10;
  range.range_max = 300000;
  range.range_step = 1;
  const DevicePropDesc range_out = DecodeDevicePropDesc(Encode(range));
  EXPECT_EQ(range_out.range_max, 300000u);
  EXPECT_EQ(range_out.current, 80u);

  EXPECT_EQ(DecodePropValue(kTypeUint8, EncodePropValue(kTypeUint8, 3)), 3u);
  EXPECT_EQ(EncodePropValue(kTypeUint32, 0x01020304), (std::vector<uint8_t>{4, 3, 2, 1}));
  EXPECT_THROW(DecodePropValue(kTypeUint16, std::vector<uint8_t>{1, 2, 3}), PtpDecodeError);
  EXPECT_THROW(EncodePropValue(0xFFFF, 1), std::invalid_argument);  // strings are not values here
}

TEST(PtpDatasets, TruncatedDatasetsAreCleanErrors) {
  const std::vector<uint8_t> info = Encode(SampleDeviceInfo());
  for (size_t size = 0; size < info.size(); ++size) {
    EXPECT_THROW(DecodeDeviceInfo(std::span(info.data(), size)), PtpDecodeError) << size;
  }
  std::vector<uint8_t> longer = info;
  longer.push_back(0);
  EXPECT_THROW(DecodeDeviceInfo(longer), PtpDecodeError);

  // An array claiming four billion entries must not allocate them.
  ByteWriter w;
  w.U16(100);
  w.U32(0);
  w.U16(0);
  w.PtpString("");
  w.U16(0);
  w.U32(0xFFFFFFFF);
  try {
    DecodeDeviceInfo(w.bytes());
    FAIL();
  } catch (const PtpDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("operations supported"), std::string::npos) << e.what();
  }

  const std::vector<uint8_t> desc = Encode(DevicePropDesc{
      kPropFNumber, kTypeUint16, kPropGetSet, 800, 800, kFormEnumeration, {400, 800}});
  for (size_t size = 0; size < desc.size(); ++size) {
    EXPECT_THROW(DecodeDevicePropDesc(std::span(desc.data(), size)), PtpDecodeError) << size;
  }
}

}  // namespace
}  // namespace avc::sim::ptp
