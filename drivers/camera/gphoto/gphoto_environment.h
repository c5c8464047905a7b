#pragma once

// What libgphoto2 needs around it before a camera can be opened.

#include <string>

namespace avc::camera_driver {

// libgphoto2 keeps its settings (PTP/IP GUID, capture target) in $HOME/.gphoto/settings and
// silently misbehaves without it. Creates $HOME/.gphoto if needed; throws CameraError kFailed
// saying so when HOME is unset or not writable.
void RequireWritableGphotoHome();

// libgphoto2 2.5.30 connects the PTP/IP event channel to port 15740 unless the path names it
// ("ptpip:HOST:PORT:EVENTPORT"), so "ptpip:HOST:PORT" gets ":PORT" appended: a camera on a
// non-default port serves both channels there. Other paths are returned unchanged.
std::string NormalizePortPath(const std::string& path);

}  // namespace avc::camera_driver
