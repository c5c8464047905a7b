#pragma once

// The camera bodies avc-camera watches for on USB (hot-plug re-initialises the camera at once
// instead of waiting for the next reconnect attempt). Add a body here when a lab uses another.

#include <vector>

#include "drivers/usb/usb_devices.h"

namespace avc::camera_driver {

// Canon EOS 650D / Rebel T4i (04a9:323b), the paper's camera.
const std::vector<usb::KnownUsbDevice>& KnownCameraBodies();

}  // namespace avc::camera_driver
