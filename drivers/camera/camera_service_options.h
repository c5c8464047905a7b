#pragma once

// avc-camera's options (which camera, how captures are queued and retried), declared once for
// --config, --set, the configuration it publishes and --help (core/config/option_table.h).

#include "core/config/option_table.h"
#include "drivers/camera/camera_node.h"
#include "drivers/camera/gphoto/gphoto_camera.h"

namespace avc::camera_driver {

struct CameraServiceOptions {
  GphotoCameraOptions gphoto;
  CameraNodeOptions node;
  // Watch USB for the camera being plugged in or out (only a USB camera is: not a ptpip: port).
  bool watch_usb = true;
};

const config::OptionTable<CameraServiceOptions>& CameraOptionTable();

}  // namespace avc::camera_driver
