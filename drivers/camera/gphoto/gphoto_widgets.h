#pragma once

// libgphoto2 config widgets as text: the value of any value-carrying widget, the choices of a
// radio/menu, and validated assignment (a value the camera does not offer is refused here with
// the choices listed, before anything reaches the camera).

#include <gphoto2/gphoto2-widget.h>

#include <string>
#include <vector>

namespace avc::camera_driver {

// Frees a widget tree returned by gp_camera_get_single_config.
class OwnedWidget {
 public:
  OwnedWidget() = default;
  ~OwnedWidget();
  OwnedWidget(const OwnedWidget&) = delete;
  OwnedWidget& operator=(const OwnedWidget&) = delete;
  CameraWidget** out() { return &widget_; }
  CameraWidget* get() const { return widget_; }

 private:
  CameraWidget* widget_ = nullptr;
};

// Throws CameraError kBadSetting for widgets without a value (sections, buttons).
std::string WidgetValueText(CameraWidget* widget, const std::string& setting);
// Radio/menu choices, {"0", "1"} for a toggle, empty for free-form widgets.
std::vector<std::string> WidgetChoices(CameraWidget* widget);
// Throws CameraError kBadSetting naming the setting (and its choices) for a read-only widget or
// a value it cannot take.
void SetWidgetValueText(CameraWidget* widget, const std::string& setting, const std::string& value);

}  // namespace avc::camera_driver
