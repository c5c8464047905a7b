#include "drivers/camera/gphoto/gphoto_widgets.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gphoto2/gphoto2-result.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "drivers/camera/camera_backend.h"

namespace avc::camera_driver {
namespace {

CameraError BadSetting(const std::string& text) {
  return CameraError(CameraError::Kind::kBadSetting, text);
}

CameraWidgetType TypeOf(CameraWidget* widget) {
  CameraWidgetType type = GP_WIDGET_TEXT;
  gp_widget_get_type(widget, &type);
  return type;
}

float ParseFloat(const std::string& setting, const std::string& value) {
  size_t used = 0;
  float parsed = 0;
  try {
    parsed = std::stof(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || !std::isfinite(parsed)) {
    throw BadSetting(fmt::format("camera setting '{}' needs a number, not '{}'", setting, value));
  }
  return parsed;
}

}  // namespace

OwnedWidget::~OwnedWidget() {
  if (widget_ != nullptr) gp_widget_free(widget_);
}

std::string WidgetValueText(CameraWidget* widget, const std::string& setting) {
  switch (TypeOf(widget)) {
    case GP_WIDGET_TEXT:
    case GP_WIDGET_RADIO:
    case GP_WIDGET_MENU: {
      const char* text = nullptr;
      gp_widget_get_value(widget, &text);
      return text != nullptr ? text : "";
    }
    case GP_WIDGET_TOGGLE:
    case GP_WIDGET_DATE: {
      int value = 0;
      gp_widget_get_value(widget, &value);
      return std::to_string(value);
    }
    case GP_WIDGET_RANGE: {
      float value = 0;
      gp_widget_get_value(widget, &value);
      return fmt::format("{}", value);
    }
    default:
      throw BadSetting(
          fmt::format("camera setting '{}' is a section or button, not a value", setting));
  }
}

std::vector<std::string> WidgetChoices(CameraWidget* widget) {
  std::vector<std::string> choices;
  const CameraWidgetType type = TypeOf(widget);
  if (type == GP_WIDGET_TOGGLE) return {"0", "1"};
  if (type != GP_WIDGET_RADIO && type != GP_WIDGET_MENU) return choices;
  const int count = gp_widget_count_choices(widget);
  for (int i = 0; i < count; ++i) {
    const char* choice = nullptr;
    if (gp_widget_get_choice(widget, i, &choice) == GP_OK && choice != nullptr) {
      choices.emplace_back(choice);
    }
  }
  return choices;
}

void SetWidgetValueText(CameraWidget* widget, const std::string& setting,
                        const std::string& value) {
  int read_only = 0;
  gp_widget_get_readonly(widget, &read_only);
  if (read_only != 0) throw BadSetting(fmt::format("camera setting '{}' is read-only", setting));
  int result = GP_OK;
  switch (TypeOf(widget)) {
    case GP_WIDGET_RADIO:
    case GP_WIDGET_MENU:
    case GP_WIDGET_TOGGLE: {
      const std::vector<std::string> choices = WidgetChoices(widget);
      if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
        throw BadSetting(fmt::format("camera setting '{}' has no value '{}'; choices: {}", setting,
                                     value, fmt::join(choices, ", ")));
      }
      if (TypeOf(widget) == GP_WIDGET_TOGGLE) {
        const int on = value == "1" ? 1 : 0;
        result = gp_widget_set_value(widget, &on);
      } else {
        result = gp_widget_set_value(widget, value.c_str());
      }
      break;
    }
    case GP_WIDGET_TEXT:
      result = gp_widget_set_value(widget, value.c_str());
      break;
    case GP_WIDGET_RANGE: {
      const float number = ParseFloat(setting, value);
      float min = 0, max = 0, step = 0;
      gp_widget_get_range(widget, &min, &max, &step);
      if (number < min || number > max) {
        throw BadSetting(
            fmt::format("camera setting '{}' takes {} to {}, not {}", setting, min, max, value));
      }
      result = gp_widget_set_value(widget, &number);
      break;
    }
    case GP_WIDGET_DATE: {
      const int seconds = static_cast<int>(ParseFloat(setting, value));
      result = gp_widget_set_value(widget, &seconds);
      break;
    }
    default:
      throw BadSetting(
          fmt::format("camera setting '{}' is a section or button, not a value", setting));
  }
  if (result != GP_OK) {
    throw BadSetting(fmt::format("camera setting '{}' refused '{}': {}", setting, value,
                                 gp_result_as_string(result)));
  }
}

}  // namespace avc::camera_driver
