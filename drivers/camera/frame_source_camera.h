#pragma once

// A camera whose pictures come from a function instead of a device: the in-process backend of
// `avc camera --backend sim` style use and of node tests, where the function renders the
// simulated cell or returns test frames. Settings behave like a real body's: named, validated
// against their choices, remembered.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "drivers/camera/camera_backend.h"

namespace avc::camera_driver {

struct FrameSourceSettings {
  std::map<std::string, std::string> values;
  std::map<std::string, std::vector<std::string>> choices;
};

// iso / shutterspeed / aperture / imageformat / capturetarget with Canon-like choices.
FrameSourceSettings CanonLikeSettings();

class FrameSourceCamera : public CameraBackend {
 public:
  // capture(settings) returns the next picture; preview may be empty (no live view).
  using Source = std::function<CameraImage(const std::map<std::string, std::string>& settings)>;
  FrameSourceCamera(std::string name, Source capture, Source preview = {},
                    FrameSourceSettings settings = CanonLikeSettings());

  void Open() override { open_ = true; }
  void Close() noexcept override { open_ = false; }
  bool is_open() const override { return open_; }
  std::string Describe() const override { return name_; }
  std::string GetSetting(const std::string& name) override;
  std::vector<std::string> SettingChoices(const std::string& name) override;
  void SetSetting(const std::string& name, const std::string& value) override;
  CameraImage Capture() override;
  CameraImage Preview() override;

 private:
  void RequireOpen() const;

  std::string name_;
  Source capture_;
  Source preview_;
  FrameSourceSettings settings_;
  bool open_ = false;
};

}  // namespace avc::camera_driver
