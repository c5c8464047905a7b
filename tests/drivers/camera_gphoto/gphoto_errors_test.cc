// How libgphoto2 results and messages become CameraError kinds, and PTP/IP port normalisation.

#include "drivers/camera/gphoto/gphoto_errors.h"

#include <gphoto2/gphoto2-port-result.h>
#include <gphoto2/gphoto2-result.h>
#include <gtest/gtest.h>

#include "drivers/camera/gphoto/gphoto_environment.h"

namespace avc::camera_driver {
namespace {

using Kind = CameraError::Kind;

TEST(GphotoErrors, ResultCodesMapToKinds) {
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR_CAMERA_BUSY, {}), Kind::kBusy);
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR_NOT_SUPPORTED, {}), Kind::kUnsupported);
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR_IO, {}), Kind::kDisconnected);
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR_IO_USB_FIND, {}), Kind::kDisconnected);
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR_TIMEOUT, {}), Kind::kDisconnected);
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR_IO_USB_CLAIM, {}), Kind::kFailed);
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR, {}), Kind::kFailed);
}

TEST(GphotoErrors, MessagesRefineUnspecifiedErrors) {
  GphotoDiagnostics busy;
  busy.context_errors = {"Full-Press failed (0x2019: PTP Device Busy)"};
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR, busy), Kind::kBusy);
  GphotoDiagnostics gone;
  gone.log_errors = {"ptp_ptpip_generic_read: End of stream after reading 0 bytes of ptpipheader"};
  EXPECT_EQ(ClassifyGphotoError(GP_ERROR, gone), Kind::kDisconnected);
}

TEST(GphotoErrors, ClaimFailureExplainsWhoHoldsTheCamera) {
  const CameraError error =
      MakeGphotoError("Canon EOS 650D on usb:001,004", "initialising", GP_ERROR_IO_USB_CLAIM, {});
  EXPECT_EQ(error.kind(), Kind::kFailed);
  const std::string text = error.what();
  EXPECT_NE(text.find("usb:001,004"), std::string::npos) << text;
  EXPECT_NE(text.find("(-53)"), std::string::npos) << text;
  EXPECT_NE(text.find("gvfs-gphoto2-volume-monitor"), std::string::npos) << text;
}

TEST(GphotoErrors, MessageCarriesContextAndLastLogLines) {
  GphotoDiagnostics d;
  d.context_errors = {"Could not capture."};
  d.log_errors = {"a", "b", "c", "d"};
  const std::string text = MakeGphotoError("cam", "capture", GP_ERROR, d).what();
  EXPECT_NE(text.find("cam: capture failed"), std::string::npos) << text;
  EXPECT_NE(text.find("Could not capture."), std::string::npos) << text;
  EXPECT_EQ(text.find("; a"), std::string::npos) << "only the last three log lines: " << text;
  EXPECT_NE(text.find("; d"), std::string::npos) << text;
}

TEST(GphotoEnvironment, PtpIpPathsNameTheirEventPort) {
  EXPECT_EQ(NormalizePortPath("ptpip:127.0.0.1:15741"), "ptpip:127.0.0.1:15741:15741");
  EXPECT_EQ(NormalizePortPath("ptpip:127.0.0.1:15741:15742"), "ptpip:127.0.0.1:15741:15742");
  EXPECT_EQ(NormalizePortPath("ptpip:192.168.1.5"), "ptpip:192.168.1.5");
  EXPECT_EQ(NormalizePortPath("usb:001,004"), "usb:001,004");
  EXPECT_EQ(NormalizePortPath(""), "");
}

}  // namespace
}  // namespace avc::camera_driver
