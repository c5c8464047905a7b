#include "drivers/camera/known_cameras.h"

namespace avc::camera_driver {

const std::vector<usb::KnownUsbDevice>& KnownCameraBodies() {
  static const std::vector<usb::KnownUsbDevice> bodies = {
      {0x04a9, 0x323b, "Canon EOS 650D / Rebel T4i"},
  };
  return bodies;
}

}  // namespace avc::camera_driver
