// avc camera: the avc-camera service (libgphoto2: a USB camera or the simulated cell's PTP/IP
// camera), `avc camera list` to find cameras, `avc camera snap` for one picture without the bus.

#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <memory>

#include "core/bus/service_runtime.h"
#include "drivers/camera/camera_node.h"
#include "drivers/camera/camera_service_options.h"
#include "drivers/camera/gphoto/gphoto_camera.h"
#include "drivers/camera/known_cameras.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/usb_listing.h"

namespace avc::cli {
namespace {

struct CameraArgs {
  ConfigFlags config;
  bus::BusFlags bus;
};

struct SnapArgs {
  camera_driver::GphotoCameraOptions gphoto;
  std::vector<std::string> settings;  // name=value
  std::string output;
};

int RunCamera(const CameraArgs& args) {
  const auto& table = camera_driver::CameraOptionTable();
  camera_driver::CameraServiceOptions options = LoadOptions(table, args.config);
  // Hot-plug only means something for a USB camera.
  options.node.watch_usb = options.watch_usb && options.gphoto.port.rfind("ptpip:", 0) != 0;
  bus::ServiceRuntime runtime(options.node.service, args.bus);
  runtime.PublishConfig(table.ToToml(options));
  camera_driver::CameraNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(),
                                 std::make_unique<camera_driver::GphotoCamera>(options.gphoto),
                                 options.node);
  runtime.OnStop([&] { node.Shutdown(); });
  return runtime.Run();
}

int RunList(double watch_s) {
  std::vector<camera_driver::DetectedCamera> detected;
  try {
    detected = camera_driver::ListCameras();
  } catch (const camera_driver::CameraError& error) {
    std::cout << "libgphoto2 could not look for cameras: " << error.what() << "\n";
  }
  std::cout << (detected.empty() ? "libgphoto2 detects no camera\n" : "libgphoto2 detects:\n");
  for (const auto& camera : detected) {
    std::cout << fmt::format("  {} on {}\n", camera.model, camera.port);
  }
  return ListUsbDevices(camera_driver::KnownCameraBodies(), "known camera bodies on USB", watch_s);
}

int RunSnap(const SnapArgs& args) {
  camera_driver::GphotoCamera camera(args.gphoto);
  camera.Open();
  std::cout << "opened " << camera.Describe() << std::endl;
  for (const std::string& setting : args.settings) {
    const size_t equals = setting.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw std::invalid_argument("--set wants name=value, got '" + setting + "'");
    }
    camera.SetSetting(setting.substr(0, equals), setting.substr(equals + 1));
  }
  const camera_driver::CameraImage image = camera.Capture();
  std::ofstream out(args.output, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(image.data.data()),
            static_cast<std::streamsize>(image.data.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write " + args.output);
  std::cout << fmt::format("wrote {} ({} bytes, {} from the camera as {})\n", args.output,
                           image.data.size(), image.mime_type, image.file_name);
  return 0;
}

void AddCameraSelection(CLI::App& command, camera_driver::GphotoCameraOptions& options) {
  command
      .add_option("--port", options.port,
                  "libgphoto2 port: usb:BUS,DEV, ptpip:HOST:PORT (default: autodetect)")
      ->capture_default_str();
  command.add_option("--model", options.model,
                     "libgphoto2 model, e.g. \"Canon EOS 650D\" (default: autodetect)");
}

}  // namespace

void RegisterCamera(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<CameraArgs>();
  CLI::App* command = root.add_subcommand(
      "camera",
      "Run the avc-camera service (Canon EOS 650D or any libgphoto2 camera).\n"
      "Answers CAPTURE_REQUEST and sends each picture as an image product. The camera is used\n"
      "through libgphoto2; with no --port the first detected camera is used. Against the\n"
      "simulated cell: avc camera --port ptpip:127.0.0.1:15740\n"
      "Needs a writable $HOME (libgphoto2 keeps settings in ~/.gphoto). If the camera cannot be\n"
      "claimed, stop gvfs-gphoto2-volume-monitor (or any photo importer) that holds it.");
  ConfigFlags* config = &args->config;
  AddShorthand(command, config, "--port", "gphoto.port",
               "libgphoto2 port: usb:BUS,DEV, ptpip:HOST:PORT (default: autodetect)");
  AddShorthand(command, config, "--model", "gphoto.model",
               "libgphoto2 model, e.g. \"Canon EOS 650D\" (default: autodetect)");
  AddShorthand(command, config, "--camera-id", "node.camera_id", "id stamped on every image");
  AddShorthand(command, config, "--busy-retries", "node.busy_retries", "retries of a busy camera");
  AddShorthandSwitch(command, config, "--no-usb-watch", "watch_usb", "false",
                     "do not watch USB for the camera being plugged in or out");
  AddConfigFlags(command, config, camera_driver::CameraOptionTable().Reference({}));
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunCamera(*args); });

  auto watch_s = std::make_shared<double>(0);
  CLI::App* list = command->add_subcommand(
      "list", "List cameras libgphoto2 detects and known camera bodies on USB.");
  list->add_option("--watch", *watch_s, "then report USB arrivals and departures for S seconds");
  SetGuardedRun(list, exit_code, [watch_s] { return RunList(*watch_s); });

  auto snap = std::make_shared<SnapArgs>();
  CLI::App* snap_command = command->add_subcommand(
      "snap", "Take one picture and save it (no bus): checks a camera from the lab bench.");
  AddCameraSelection(*snap_command, snap->gphoto);
  snap_command->add_option("--set", snap->settings, "a setting before the shot: iso=200, ...");
  snap_command->add_option("-o,--output", snap->output, "file to write")->required();
  SetGuardedRun(snap_command, exit_code, [snap] { return RunSnap(*snap); });
}

}  // namespace avc::cli
