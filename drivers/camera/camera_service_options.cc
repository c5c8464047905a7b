#include "drivers/camera/camera_service_options.h"

namespace avc::camera_driver {
namespace {

using Table = config::OptionTable<CameraServiceOptions>;

Table MakeTable() {
  Table table("camera", [](const CameraServiceOptions& o) { return o.node.Validate(); });
  table
      .Add("gphoto.port", [](auto& o) -> auto& { return o.gphoto.port; },
           {"", "libgphoto2 port: usb:BUS,DEV, ptpip:HOST:PORT (\"\": autodetect)"})
      .Add("gphoto.model", [](auto& o) -> auto& { return o.gphoto.model; },
           {"", "libgphoto2 model, e.g. \"Canon EOS 650D\" (\"\": autodetect)"})
      .Add("node.camera_id", [](auto& o) -> auto& { return o.node.camera_id; },
           {"", "id stamped on every image"})
      .Add("node.busy_retries", [](auto& o) -> auto& { return o.node.busy_retries; },
           {"", "attempts after the camera first answers busy", 0, 50})
      .Add("node.busy_backoff", [](auto& o) -> auto& { return o.node.busy_backoff; },
           {"ms", "first pause after a busy answer; doubles per retry", 0, 60000})
      .Add(
          "node.reconnect_min", [](auto& o) -> auto& { return o.node.reconnect_min; },
          {"ms", "first pause before reopening the camera; doubles up to reconnect_max", 1, 600000})
      .Add("node.reconnect_max", [](auto& o) -> auto& { return o.node.reconnect_max; },
           {"ms", "longest pause between reopening attempts", 1, 600000})
      .Add("node.max_queued_captures", [](auto& o) -> auto& { return o.node.max_queued_captures; },
           {"", "capture requests held; more are refused until the queue drains", 1, 1000})
      .Add("watch_usb", [](auto& o) -> auto& { return o.watch_usb; },
           {"", "watch USB for a USB camera being plugged in or out"});
  return table;
}

}  // namespace

const config::OptionTable<CameraServiceOptions>& CameraOptionTable() {
  static const Table table = MakeTable();
  return table;
}

}  // namespace avc::camera_driver
