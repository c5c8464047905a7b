#include "drivers/camera/gphoto/gphoto_errors.h"

#include <fmt/format.h>
#include <gphoto2/gphoto2-port-result.h>
#include <gphoto2/gphoto2-result.h>

#include <algorithm>
#include <array>
#include <string_view>

namespace avc::camera_driver {
namespace {

bool AnyContains(const std::vector<std::string>& lines, std::string_view needle) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& line) {
    return line.find(needle) != std::string::npos;
  });
}

bool Mentions(const GphotoDiagnostics& d, std::string_view needle) {
  return AnyContains(d.context_errors, needle) || AnyContains(d.log_errors, needle);
}

// Log lines libgphoto2 writes when the camera's connection is gone (ptpip.c, ptp.c, usb1.c).
constexpr std::array<std::string_view, 6> kDisconnectSigns = {
    "End of stream", "PTP I/O Error",  "Connection reset",
    "Broken pipe",   "No such device", "Could not find the requested device"};

}  // namespace

CameraError::Kind ClassifyGphotoError(int gp_result, const GphotoDiagnostics& diagnostics) {
  using Kind = CameraError::Kind;
  if (gp_result == GP_ERROR_CAMERA_BUSY || Mentions(diagnostics, "Device Busy") ||
      Mentions(diagnostics, "0x2019")) {
    return Kind::kBusy;
  }
  switch (gp_result) {
    case GP_ERROR_NOT_SUPPORTED:
      return Kind::kUnsupported;
    case GP_ERROR_IO_USB_CLAIM:  // someone else holds the device: reconnecting will not help
      return Kind::kFailed;
    case GP_ERROR_IO:
    case GP_ERROR_IO_INIT:
    case GP_ERROR_IO_READ:
    case GP_ERROR_IO_WRITE:
    case GP_ERROR_IO_UPDATE:
    case GP_ERROR_IO_USB_CLEAR_HALT:
    case GP_ERROR_IO_USB_FIND:
    case GP_ERROR_TIMEOUT:
      return Kind::kDisconnected;
    default:
      break;
  }
  for (std::string_view sign : kDisconnectSigns) {
    if (Mentions(diagnostics, sign)) return Kind::kDisconnected;
  }
  return Kind::kFailed;
}

CameraError MakeGphotoError(const std::string& who, const std::string& what, int gp_result,
                            const GphotoDiagnostics& diagnostics) {
  std::string text =
      fmt::format("{}: {} failed: {} ({})", who, what, gp_result_as_string(gp_result), gp_result);
  // The context messages are libgphoto2's own explanation; a few log lines add the low-level why.
  for (const std::string& line : diagnostics.context_errors) text += "; " + line;
  const size_t log_lines = std::min<size_t>(diagnostics.log_errors.size(), 3);
  for (size_t i = diagnostics.log_errors.size() - log_lines; i < diagnostics.log_errors.size();
       ++i) {
    text += "; " + diagnostics.log_errors[i];
  }
  const CameraError::Kind kind = ClassifyGphotoError(gp_result, diagnostics);
  if (kind == CameraError::Kind::kDisconnected) {
    // Quote the line that showed the connection is gone when the tail above does not.
    for (const std::string& line : diagnostics.log_errors) {
      const bool sign = std::any_of(kDisconnectSigns.begin(), kDisconnectSigns.end(),
                                    [&](std::string_view s) { return line.find(s) != line.npos; });
      if (sign && text.find(line) == std::string::npos) {
        text += "; connection lost: " + line;
        break;
      }
    }
  }
  if (gp_result == GP_ERROR_IO_USB_CLAIM) {
    text +=
        ". Another program holds the camera: usually gvfs-gphoto2-volume-monitor or gvfsd-gphoto2 "
        "(stop it, or run `gio mount -s gphoto2`), or a second avc-camera / gphoto2 process";
  }
  return CameraError(kind, text);
}

}  // namespace avc::camera_driver
