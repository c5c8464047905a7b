#include "drivers/camera/camera_backend.h"

namespace avc::camera_driver {

const char* CameraErrorKindName(CameraError::Kind kind) {
  switch (kind) {
    case CameraError::Kind::kBusy:
      return "busy";
    case CameraError::Kind::kDisconnected:
      return "disconnected";
    case CameraError::Kind::kUnsupported:
      return "unsupported";
    case CameraError::Kind::kBadSetting:
      return "bad setting";
    case CameraError::Kind::kFailed:
      return "failed";
  }
  return "unknown";
}

}  // namespace avc::camera_driver
