#pragma once

// CameraBackend over libgphoto2: a real camera on USB (Canon EOS 650D) or any camera libgphoto2
// can open, including the PTP/IP emulator (model "PTP/IP Camera", port "ptpip:127.0.0.1:PORT").
// The pitfalls this works around are listed below.
//
// Not thread-safe: one owner thread per camera, as the USB device has one owner.
// Process-wide side effects, both to survive libgphoto2 2.5.30's PTP/IP code:
//  - Open() sets SIGPIPE to ignored if it was at its default: libgphoto2 write()s to sockets the
//    camera may have closed, which would otherwise kill the process;
//  - fd 0 is kept open (/dev/null if it was closed) and restored after a camera is closed,
//    because libgphoto2 closes fd 0 when it disconnects a PTP/IP camera (fd0_guard.h).

#include <memory>
#include <string>
#include <vector>

#include "drivers/camera/camera_backend.h"

struct _Camera;
struct _CameraWidget;

namespace avc::camera_driver {

class GphotoCallLog;

struct GphotoCameraOptions {
  std::string model;  // libgphoto2 model name; "" = the first autodetected camera
                      // ("PTP/IP Camera" when port is a ptpip: path)
  std::string port;   // "" = autodetect, "usb:001,004", "ptpip:127.0.0.1:15740"
};

class GphotoCamera final : public CameraBackend {
 public:
  explicit GphotoCamera(GphotoCameraOptions options);
  ~GphotoCamera() override;
  GphotoCamera(const GphotoCamera&) = delete;
  GphotoCamera& operator=(const GphotoCamera&) = delete;

  void Open() override;
  void Close() noexcept override;
  bool is_open() const override { return camera_ != nullptr; }
  std::string Describe() const override;

  // Names are libgphoto2's config names. The generic PTP driver calls FNumber "f-number" where
  // the Canon and Nikon drivers say "aperture"; either name finds whichever the camera has.
  std::string GetSetting(const std::string& name) override;
  std::vector<std::string> SettingChoices(const std::string& name) override;
  void SetSetting(const std::string& name, const std::string& value) override;

  CameraImage Capture() override;
  CameraImage Preview() override;

 private:
  void RequireOpen(const char* what) const;
  [[noreturn]] void Fail(const std::string& what, int gp_result) const;
  // Config names to try for a requested name (the name, then its alias).
  std::vector<std::string> ConfigNames(const std::string& name) const;
  // Fetches the named widget into `widget`; throws kBadSetting listing the known names.
  std::string FetchWidget(const std::string& name, struct _CameraWidget** widget);
  void ResolveAutodetected(std::string& model, std::string& port);
  void DrainEvents();

  GphotoCameraOptions options_;
  std::unique_ptr<GphotoCallLog> log_;
  struct _Camera* camera_ = nullptr;
  std::string model_;  // as opened
  std::string port_;
};

struct DetectedCamera {
  std::string model;
  std::string port;
};

// Cameras libgphoto2 autodetects (USB; PTP/IP cameras are not discoverable this way).
// Throws CameraError kFailed when libgphoto2 cannot enumerate.
std::vector<DetectedCamera> ListCameras();

}  // namespace avc::camera_driver
