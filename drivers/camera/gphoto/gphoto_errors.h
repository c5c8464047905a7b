#pragma once

// Turns a failed libgphoto2 call into a CameraError whose kind lets the camera node pick a
// generic policy (retry on busy, reconnect on disconnect) and whose text says what happened.

#include <string>
#include <vector>

#include "drivers/camera/camera_backend.h"

namespace avc::camera_driver {

// What libgphoto2 told us during one call besides its return code.
struct GphotoDiagnostics {
  std::vector<std::string> context_errors;  // GPContext error and message callbacks
  std::vector<std::string> log_errors;      // gp_log lines at error level
};

// The kind for a libgphoto2 result code, refined by the diagnostics: PTP Device Busy (0x2019)
// is kBusy whatever the code; a PTP/IP stream that ended or a PTP I/O error is kDisconnected even
// when libgphoto2 only says "Unspecified error".
CameraError::Kind ClassifyGphotoError(int gp_result, const GphotoDiagnostics& diagnostics);

// "<who>: <what> failed: <libgphoto2 result> (<code>): <details>", plus a hint for -53 (another
// program holds the camera).
CameraError MakeGphotoError(const std::string& who, const std::string& what, int gp_result,
                            const GphotoDiagnostics& diagnostics);

}  // namespace avc::camera_driver
