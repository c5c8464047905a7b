// The real libgphoto2 backend (stock libgphoto2, ptp2 camlib, model "PTP/IP Camera") against the
// in-process PTP/IP camera emulator: open, settings, capture + download + delete, busy and
// dropped-connection faults, live view. HOME points at a temporary directory because libgphoto2
// writes $HOME/.gphoto/settings.

#include "drivers/camera/gphoto/gphoto_camera.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "sim/emulators/ptpip/ptpip_camera.h"
#include "tests/support/test_support.h"

namespace avc::camera_driver {
namespace {

using Kind = CameraError::Kind;

// libgphoto2 reads HOME once per process, so every test shares one temporary HOME.
const std::filesystem::path& TestHome() {
  static testing::TempDir home("avc-gphoto-home");
  static const bool set = [] { return setenv("HOME", home.path().c_str(), 1) == 0; }();
  EXPECT_TRUE(set);
  return home.path();
}

// The frame source: seeded bytes behind a JPEG (or PNG) signature, a new seed per shot, and the
// settings each shot was taken with.
struct FrameLog {
  std::vector<sim::EmulatedSettings> settings;
  std::vector<std::vector<uint8_t>> frames;
  bool png = false;

  sim::EmulatedFrame Make(const sim::EmulatedSettings& s) {
    const size_t n = frames.size() + 1;
    sim::EmulatedFrame frame;
    frame.data = testing::RandomBytes(150'000 + 1000 * n, static_cast<uint32_t>(n));
    if (png) {
      const uint8_t signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
      std::copy(std::begin(signature), std::end(signature), frame.data.begin());
      frame.object_format = sim::ptp::kFormatPng;
      frame.file_name =
          "IMG_" + std::string(4 - std::to_string(n).size(), '0') + std::to_string(n) + ".PNG";
    } else {
      frame.data[0] = 0xFF;
      frame.data[1] = 0xD8;
      frame.file_name =
          "IMG_" + std::string(4 - std::to_string(n).size(), '0') + std::to_string(n) + ".JPG";
    }
    settings.push_back(s);
    frames.push_back(frame.data);
    return frame;
  }
};

class GphotoCameraTest : public ::testing::Test {
 protected:
  void SetUp() override {
    TestHome();
    sim::PtpIpCameraOptions options;
    options.frame_source = [this](const sim::EmulatedSettings& s) { return log.Make(s); };
    options.capture_latency_s = 0.5;
    emulator = std::make_unique<sim::PtpIpCamera>(std::move(options), clock);
    camera = std::make_unique<GphotoCamera>(
        GphotoCameraOptions{"PTP/IP Camera", emulator->libgphoto2_port()});
  }

  // Runs `call`, expecting a CameraError of `kind`; returns its message.
  template <class F>
  std::string ExpectError(Kind kind, F&& call) {
    try {
      call();
    } catch (const CameraError& e) {
      EXPECT_EQ(CameraErrorKindName(e.kind()), std::string(CameraErrorKindName(kind))) << e.what();
      return e.what();
    }
    ADD_FAILURE() << "no CameraError thrown";
    return "";
  }

  FrameLog log;
  // Each read advances 1 ms: the 0.5 s capture latency passes without waiting.
  std::shared_ptr<sim::SteppedEmulatorClock> clock =
      std::make_shared<sim::SteppedEmulatorClock>(0.001);
  std::unique_ptr<sim::PtpIpCamera> emulator;
  std::unique_ptr<GphotoCamera> camera;
};

TEST_F(GphotoCameraTest, OpensAndDescribes) {
  EXPECT_FALSE(camera->is_open());
  camera->Open();
  ASSERT_TRUE(camera->is_open());
  const int port = emulator->port();
  EXPECT_EQ(camera->Describe(), "PTP/IP Camera on ptpip:127.0.0.1:" + std::to_string(port) + ":" +
                                    std::to_string(port));
  EXPECT_EQ(emulator->sessions_opened(), 1);

  // The Init handshake: our host name, and the GUID libgphoto2 keeps in $HOME/.gphoto/settings.
  const std::optional<sim::PtpIpClient> client = emulator->client();
  ASSERT_TRUE(client.has_value());
  char host[256] = {};
  gethostname(host, sizeof(host) - 1);
  EXPECT_EQ(client->host_name, host);
  EXPECT_EQ(client->version, 0x00010000u);
  std::string guid;
  for (uint8_t b : client->guid) guid += fmt::format("{:02x}:", b);
  guid.pop_back();
  const std::string settings = testing::ReadFile(TestHome() / ".gphoto" / "settings");
  EXPECT_NE(settings.find("ptp2_ip=guid=" + guid), std::string::npos) << settings;

  struct stat stdin_before {};
  ASSERT_EQ(fstat(0, &stdin_before), 0);
  camera->Open();  // already open: nothing happens
  EXPECT_EQ(emulator->sessions_opened(), 1);
  camera->Close();
  camera->Close();  // idempotent
  EXPECT_FALSE(camera->is_open());
  // libgphoto2 closes fd 0 when a PTP/IP camera closes; the driver puts it back (fd0_guard.h).
  struct stat stdin_after {};
  ASSERT_EQ(fstat(0, &stdin_after), 0) << "fd 0 was closed";
  EXPECT_EQ(stdin_after.st_ino, stdin_before.st_ino);
  EXPECT_EQ(stdin_after.st_dev, stdin_before.st_dev);
  EXPECT_EQ(emulator->unsupported_requests(), 0);
}

TEST_F(GphotoCameraTest, SettingsRoundTripToTheCamera) {
  camera->Open();
  EXPECT_EQ(camera->GetSetting("iso"), "100");
  EXPECT_EQ(camera->SettingChoices("iso"),
            (std::vector<std::string>{"100", "200", "400", "800", "1600", "3200", "6400"}));
  camera->SetSetting("iso", "800");
  EXPECT_EQ(camera->GetSetting("iso"), "800");
  EXPECT_EQ(emulator->settings().iso, 800u);

  EXPECT_EQ(camera->GetSetting("shutterspeed"), "0.0080s");
  camera->SetSetting("shutterspeed", "0.0040s");
  EXPECT_DOUBLE_EQ(emulator->settings().shutter_s, 0.004);

  // The generic PTP driver names FNumber "f-number"; "aperture" (Canon/Nikon) finds it too.
  EXPECT_EQ(camera->GetSetting("aperture"), "f/8");
  camera->SetSetting("aperture", "f/5.6");
  EXPECT_DOUBLE_EQ(emulator->settings().f_number, 5.6);
  EXPECT_EQ(camera->GetSetting("f-number"), "f/5.6");
  EXPECT_EQ(emulator->unsupported_requests(), 0);
}

TEST_F(GphotoCameraTest, BadSettingsNameTheChoices) {
  camera->Open();
  const std::string bad_value =
      ExpectError(Kind::kBadSetting, [&] { camera->SetSetting("iso", "123"); });
  EXPECT_NE(bad_value.find("'iso'"), std::string::npos) << bad_value;
  EXPECT_NE(bad_value.find("'123'"), std::string::npos) << bad_value;
  EXPECT_NE(bad_value.find("100, 200, 400, 800, 1600, 3200, 6400"), std::string::npos) << bad_value;
  EXPECT_EQ(emulator->settings().iso, 100u);

  const std::string bad_name =
      ExpectError(Kind::kBadSetting, [&] { camera->GetSetting("whitebalance"); });
  EXPECT_NE(bad_name.find("no setting named 'whitebalance'"), std::string::npos) << bad_name;
  EXPECT_NE(bad_name.find("iso"), std::string::npos) << bad_name;
  EXPECT_NE(bad_name.find("shutterspeed"), std::string::npos) << bad_name;
  // Still usable afterwards.
  EXPECT_EQ(camera->GetSetting("iso"), "100");
}

TEST_F(GphotoCameraTest, CaptureDownloadsExactBytesAndEmptiesTheCard) {
  camera->Open();
  camera->SetSetting("iso", "400");
  const double before_s = clock->NowSeconds();
  const CameraImage image = camera->Capture();
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(image.data, log.frames[0]);
  EXPECT_EQ(image.file_name, "IMG_0001.JPG");
  EXPECT_EQ(image.mime_type, "image/jpeg");
  EXPECT_EQ(log.settings[0].iso, 400u);
  EXPECT_EQ(emulator->captures(), 1);
  EXPECT_EQ(emulator->objects_stored(), 0);
  // The capture waited out its 0.5 s latency on the emulator clock.
  EXPECT_GE(clock->NowSeconds() - before_s, 0.5);
}

TEST_F(GphotoCameraTest, ThreeCapturesInARow) {
  log.png = true;
  camera->Open();
  for (int i = 0; i < 3; ++i) {
    const CameraImage image = camera->Capture();
    ASSERT_EQ(log.frames.size(), static_cast<size_t>(i + 1));
    EXPECT_EQ(image.data, log.frames[i]) << "shot " << i;
    EXPECT_EQ(image.file_name, "IMG_000" + std::to_string(i + 1) + ".PNG");
    EXPECT_EQ(image.mime_type, "image/png");
  }
  EXPECT_NE(log.frames[0], log.frames[1]);
  EXPECT_EQ(emulator->captures(), 3);
  EXPECT_EQ(emulator->objects_stored(), 0);
  EXPECT_EQ(emulator->unsupported_requests(), 0);
}

TEST_F(GphotoCameraTest, BusyCameraThenSuccess) {
  camera->Open();
  emulator->InjectBusy(1);
  const std::string busy = ExpectError(Kind::kBusy, [&] { camera->Capture(); });
  EXPECT_NE(busy.find("capture failed"), std::string::npos) << busy;
  EXPECT_EQ(emulator->captures(), 0);
  const CameraImage image = camera->Capture();
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(image.data, log.frames[0]);
  EXPECT_EQ(emulator->objects_stored(), 0);
}

TEST_F(GphotoCameraTest, DroppedConnectionThenReopen) {
  camera->Open();
  camera->Capture();
  emulator->DropConnections();
  const std::string gone = ExpectError(Kind::kDisconnected, [&] { camera->Capture(); });
  EXPECT_NE(gone.find("PTP/IP Camera on ptpip:127.0.0.1"), std::string::npos) << gone;
  EXPECT_NE(gone.find("connection lost"), std::string::npos) << gone;
  camera->Close();
  camera->Open();
  const CameraImage image = camera->Capture();
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(image.data, log.frames[1]);
  EXPECT_EQ(emulator->sessions_opened(), 2);
  EXPECT_EQ(emulator->objects_stored(), 0);
}

TEST_F(GphotoCameraTest, GenericPtpIpHasNoLiveView) {
  camera->Open();
  const std::string text = ExpectError(Kind::kUnsupported, [&] { camera->Preview(); });
  EXPECT_NE(text.find("no live view"), std::string::npos) << text;
  // The camera is still fine afterwards.
  EXPECT_EQ(camera->GetSetting("iso"), "100");
}

TEST_F(GphotoCameraTest, CallsOnAClosedCameraFailClearly) {
  const std::string text = ExpectError(Kind::kFailed, [&] { camera->Capture(); });
  EXPECT_NE(text.find("Open()"), std::string::npos) << text;
  ExpectError(Kind::kFailed, [&] { camera->GetSetting("iso"); });
}

TEST_F(GphotoCameraTest, UnknownModelAndNoListenerFail) {
  GphotoCamera unknown({"No Such Camera 9000", emulator->libgphoto2_port()});
  const std::string model = ExpectError(Kind::kFailed, [&] { unknown.Open(); });
  EXPECT_NE(model.find("No Such Camera 9000"), std::string::npos) << model;
  EXPECT_FALSE(unknown.is_open());

  const std::string port = emulator->libgphoto2_port();
  emulator->Stop();
  const std::string refused = ExpectError(Kind::kDisconnected, [&] { camera->Open(); });
  EXPECT_NE(refused.find("initialising failed"), std::string::npos) << refused;
  EXPECT_FALSE(camera->is_open());
}

TEST_F(GphotoCameraTest, OpenNeedsAWritableHome) {
  TestHome();
  const std::string saved = std::getenv("HOME");
  unsetenv("HOME");
  const std::string unset = ExpectError(Kind::kFailed, [&] { camera->Open(); });
  EXPECT_NE(unset.find("HOME is not set"), std::string::npos) << unset;
  setenv("HOME", "/proc/avc-no-such-home", 1);
  const std::string unwritable = ExpectError(Kind::kFailed, [&] { camera->Open(); });
  EXPECT_NE(unwritable.find("not writable"), std::string::npos) << unwritable;
  setenv("HOME", saved.c_str(), 1);
  camera->Open();
  EXPECT_TRUE(camera->is_open());
}

TEST(GphotoCameraList, ListsWhatLibgphoto2Autodetects) {
  TestHome();
  // CI has no USB camera and PTP/IP cameras are not discoverable: the list may be empty, but
  // every entry must name a model and a port.
  const std::vector<DetectedCamera> cameras = ListCameras();
  for (const DetectedCamera& camera : cameras) {
    EXPECT_FALSE(camera.model.empty());
    EXPECT_FALSE(camera.port.empty());
  }
}

}  // namespace
}  // namespace avc::camera_driver
