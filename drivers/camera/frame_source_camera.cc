#include "drivers/camera/frame_source_camera.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <utility>

namespace avc::camera_driver {

FrameSourceSettings CanonLikeSettings() {
  FrameSourceSettings settings;
  settings.choices = {
      {"iso", {"100", "200", "400", "800", "1600", "3200", "6400"}},
      {"shutterspeed", {"1/1000", "1/500", "1/250", "1/125", "1/60", "1/30", "1/15"}},
      {"aperture", {"5.6", "8", "11", "16", "22"}},
      {"imageformat", {"Large Fine JPEG", "RAW"}},
      {"capturetarget", {"Internal RAM", "Memory card"}},
  };
  settings.values = {{"iso", "200"},
                     {"shutterspeed", "1/125"},
                     {"aperture", "11"},
                     {"imageformat", "Large Fine JPEG"},
                     {"capturetarget", "Internal RAM"}};
  return settings;
}

FrameSourceCamera::FrameSourceCamera(std::string name, Source capture, Source preview,
                                     FrameSourceSettings settings)
    : name_(std::move(name)),
      capture_(std::move(capture)),
      preview_(std::move(preview)),
      settings_(std::move(settings)) {}

void FrameSourceCamera::RequireOpen() const {
  if (!open_) throw CameraError(CameraError::Kind::kDisconnected, name_ + " is not open");
}

std::vector<std::string> FrameSourceCamera::SettingChoices(const std::string& name) {
  RequireOpen();
  const auto it = settings_.choices.find(name);
  if (it == settings_.choices.end()) {
    throw CameraError(CameraError::Kind::kBadSetting,
                      fmt::format("{} has no setting '{}'", name_, name));
  }
  return it->second;
}

std::string FrameSourceCamera::GetSetting(const std::string& name) {
  SettingChoices(name);  // validates the name
  return settings_.values[name];
}

void FrameSourceCamera::SetSetting(const std::string& name, const std::string& value) {
  const std::vector<std::string> choices = SettingChoices(name);
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    throw CameraError(CameraError::Kind::kBadSetting,
                      fmt::format("{}: '{}' is not a choice of {} ({})", name_, value, name,
                                  fmt::join(choices, ", ")));
  }
  settings_.values[name] = value;
}

CameraImage FrameSourceCamera::Capture() {
  RequireOpen();
  return capture_(settings_.values);
}

CameraImage FrameSourceCamera::Preview() {
  RequireOpen();
  if (!preview_) {
    throw CameraError(CameraError::Kind::kUnsupported, name_ + " has no live view");
  }
  return preview_(settings_.values);
}

}  // namespace avc::camera_driver
