#pragma once

// What avc-camera needs from a camera, whatever talks to it: libgphoto2 for a real (or PTP/IP
// emulated) camera, or the in-process renderer. The node owns retry and reconnection policy;
// a backend reports what went wrong through CameraError's kind so that policy can be generic.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace avc::camera_driver {

class CameraError : public std::runtime_error {
 public:
  enum class Kind {
    kBusy,          // the camera asked us to try again later (PTP 0x2019 Device Busy)
    kDisconnected,  // the camera went away; Close() then Open() again
    kUnsupported,   // this camera cannot do that (e.g. no live view)
    kBadSetting,    // unknown setting name or a value the camera does not offer
    kFailed,        // anything else
  };
  CameraError(Kind kind, const std::string& what) : std::runtime_error(what), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

const char* CameraErrorKindName(CameraError::Kind kind);

// One image as the camera delivered it (encoded: JPEG, PNG or RAW file bytes).
struct CameraImage {
  std::vector<uint8_t> data;
  std::string file_name;  // as the camera named it, e.g. "IMG_0001.JPG"
  std::string mime_type;  // "image/jpeg", "image/png", ...
};

class CameraBackend {
 public:
  virtual ~CameraBackend() = default;

  // Connects and initialises the camera. Throws CameraError.
  virtual void Open() = 0;
  // Releases the camera (the device is free for another owner afterwards). Never throws.
  virtual void Close() noexcept = 0;
  virtual bool is_open() const = 0;

  // "Canon EOS 650D on usb:001,004", "PTP/IP Camera on ptpip:127.0.0.1:15740", ...
  virtual std::string Describe() const = 0;

  // Settings by the camera's own names (iso, shutterspeed, aperture, imageformat, capturetarget).
  // Throws CameraError (kBadSetting names the setting and, for a bad value, the choices).
  virtual std::string GetSetting(const std::string& name) = 0;
  virtual std::vector<std::string> SettingChoices(const std::string& name) = 0;
  virtual void SetSetting(const std::string& name, const std::string& value) = 0;

  // Takes one full image, downloads it and removes it from the camera. Throws CameraError.
  virtual CameraImage Capture() = 0;
  // One live-view frame (JPEG) for framing. Throws CameraError (kUnsupported without live view).
  virtual CameraImage Preview() = 0;
};

}  // namespace avc::camera_driver
