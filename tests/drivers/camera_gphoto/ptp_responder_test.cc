// The emulator's PTP logic without sockets: sessions, unknown opcodes, property validation,
// busy injection and the object store's handles.

#include "sim/emulators/ptpip/ptp_responder.h"

#include <gtest/gtest.h>

#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim::ptp {
namespace {

OperationRequest Op(uint16_t code, std::vector<uint32_t> params = {}) {
  static uint32_t tid = 0;
  return OperationRequest{1, code, ++tid, std::move(params)};
}

EmulatedFrame Frame(std::string name) {
  EmulatedFrame frame;
  frame.data = {0xFF, 0xD8, 0xFF, 0xD9};
  frame.file_name = std::move(name);
  return frame;
}

class PtpResponderTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(responder.Handle(Op(kOpOpenSession, {1}), {}).code, kRcOk); }
  PtpResponder responder{DeviceIdentity{}};
};

TEST(PtpResponder, NeedsASession) {
  PtpResponder responder{DeviceIdentity{}};
  EXPECT_EQ(responder.Handle(Op(kOpGetDeviceInfo), {}).code, kRcOk);
  EXPECT_EQ(responder.Handle(Op(kOpGetStorageIds), {}).code, kRcSessionNotOpen);
  EXPECT_EQ(responder.Handle(Op(kOpOpenSession, {0}), {}).code, kRcParameterNotSupported);
  EXPECT_EQ(responder.Handle(Op(kOpOpenSession, {1}), {}).code, kRcOk);
  EXPECT_EQ(responder.Handle(Op(kOpOpenSession, {1}), {}).code, kRcSessionAlreadyOpen);
  EXPECT_EQ(responder.sessions_opened(), 1);
  responder.EndSession();
  EXPECT_EQ(responder.Handle(Op(kOpGetStorageIds), {}).code, kRcSessionNotOpen);
}

TEST_F(PtpResponderTest, UnknownOperationsAreNotSupported) {
  for (uint16_t code : {uint16_t{0x1006}, uint16_t{0x100C}, uint16_t{0x9116}, uint16_t{0x9999}}) {
    EXPECT_EQ(responder.Handle(Op(code), {}).code, kRcOperationNotSupported) << code;
  }
  // What DeviceInfo advertises is exactly what is implemented.
  const DeviceInfo info = DecodeDeviceInfo(*responder.Handle(Op(kOpGetDeviceInfo), {}).data);
  EXPECT_EQ(info.operations, PtpResponder::SupportedOperations());
  for (uint16_t code : info.operations) {
    EXPECT_NE(responder.Handle(Op(code, {0x500F}), {}).code, kRcOperationNotSupported) << code;
  }
}

TEST_F(PtpResponderTest, PropertiesValidateValues) {
  const std::vector<uint8_t> iso_800 = EncodePropValue(kTypeUint16, 800);
  EXPECT_EQ(responder.Handle(Op(kOpSetDevicePropValue, {kPropExposureIndex}), iso_800).code, kRcOk);
  EXPECT_EQ(responder.settings().iso, 800u);
  const PtpResult value = responder.Handle(Op(kOpGetDevicePropValue, {kPropExposureIndex}), {});
  EXPECT_EQ(DecodePropValue(kTypeUint16, *value.data), 800u);

  const std::vector<uint8_t> iso_123 = EncodePropValue(kTypeUint16, 123);
  EXPECT_EQ(responder.Handle(Op(kOpSetDevicePropValue, {kPropExposureIndex}), iso_123).code,
            kRcInvalidDevicePropValue);
  EXPECT_EQ(responder.Handle(Op(kOpSetDevicePropValue, {kPropExposureIndex}), {1, 2, 3}).code,
            kRcInvalidDevicePropFormat);
  EXPECT_EQ(responder.Handle(Op(kOpGetDevicePropDesc, {0x5001}), {}).code,
            kRcDevicePropNotSupported);
  EXPECT_EQ(responder.settings().iso, 800u);

  const std::vector<uint8_t> shutter = EncodePropValue(kTypeUint32, 40);
  EXPECT_EQ(responder.Handle(Op(kOpSetDevicePropValue, {kPropExposureTime}), shutter).code, kRcOk);
  EXPECT_DOUBLE_EQ(responder.settings().shutter_s, 0.004);
  EXPECT_DOUBLE_EQ(responder.settings().f_number, 8.0);
}

TEST_F(PtpResponderTest, BusyInjectionCountsDown) {
  responder.InjectBusy(2);
  EXPECT_EQ(responder.Handle(Op(kOpInitiateCapture, {0, 0}), {}).code, kRcDeviceBusy);
  EXPECT_EQ(responder.Handle(Op(kOpInitiateCapture, {0, 0}), {}).code, kRcDeviceBusy);
  const PtpResult accepted = responder.Handle(Op(kOpInitiateCapture, {0, 0}), {});
  EXPECT_EQ(accepted.code, kRcOk);
  EXPECT_TRUE(accepted.start_capture);
}

TEST_F(PtpResponderTest, ObjectsAreListedReadAndDeleted) {
  const uint32_t first = responder.store().Add(Frame("IMG_0001.JPG"));
  const uint32_t second = responder.store().Add(Frame("IMG_0002.JPG"));
  EXPECT_EQ(second, first + 1);

  const PtpResult handles =
      responder.Handle(Op(kOpGetObjectHandles, {0xFFFFFFFF, 0, 0xFFFFFFFF}), {});
  ByteReader reader(*handles.data, "handles");
  EXPECT_EQ(reader.U32Array("handles"), (std::vector<uint32_t>{first, second}));

  const ObjectInfo info =
      DecodeObjectInfo(*responder.Handle(Op(kOpGetObjectInfo, {second}), {}).data);
  EXPECT_EQ(info.filename, "IMG_0002.JPG");
  EXPECT_EQ(info.compressed_size, 4u);

  const PtpResult partial = responder.Handle(Op(kOpGetPartialObject, {first, 1, 2}), {});
  EXPECT_EQ(*partial.data, (std::vector<uint8_t>{0xD8, 0xFF}));
  EXPECT_EQ(partial.params, std::vector<uint32_t>{2});

  EXPECT_EQ(responder.Handle(Op(kOpDeleteObject, {first}), {}).code, kRcOk);
  EXPECT_EQ(responder.Handle(Op(kOpDeleteObject, {first}), {}).code, kRcInvalidObjectHandle);
  EXPECT_EQ(responder.Handle(Op(kOpGetObject, {first}), {}).code, kRcInvalidObjectHandle);
  EXPECT_EQ(responder.store().size(), 1u);
  // Handles are never reused.
  EXPECT_EQ(responder.store().Add(Frame("IMG_0003.JPG")), second + 1);
}

TEST(PtpObjectStore, RefusesUnusableFrames) {
  ObjectStore store;
  EXPECT_THROW(store.Add(EmulatedFrame{}), std::invalid_argument);
  EmulatedFrame tiff = Frame("x.tif");
  tiff.object_format = 0x380D;
  EXPECT_THROW(store.Add(tiff), std::invalid_argument);
  EXPECT_THROW(store.Add(Frame("")), std::invalid_argument);
  EXPECT_EQ(store.size(), 0u);
}

}  // namespace
}  // namespace avc::sim::ptp
