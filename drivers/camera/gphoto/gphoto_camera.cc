#include "drivers/camera/gphoto/gphoto_camera.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gphoto2/gphoto2-abilities-list.h>
#include <gphoto2/gphoto2-camera.h>
#include <gphoto2/gphoto2-port-info-list.h>
#include <gphoto2/gphoto2-result.h>

#include <csignal>
#include <cstdlib>
#include <cstring>

#include "core/util/log.h"
#include "drivers/camera/gphoto/fd0_guard.h"
#include "drivers/camera/gphoto/gphoto_call_log.h"
#include "drivers/camera/gphoto/gphoto_environment.h"
#include "drivers/camera/gphoto/gphoto_errors.h"
#include "drivers/camera/gphoto/gphoto_widgets.h"

namespace avc::camera_driver {
namespace {

constexpr const char* kPtpIpModel = "PTP/IP Camera";
// Event draining after a capture: short waits until libgphoto2 reports a timeout.
constexpr int kDrainWaitMs = 10;
constexpr int kMaxDrainedEvents = 64;

struct Alias {
  const char* name;
  const char* alias;
};
constexpr Alias kAliases[] = {{"aperture", "f-number"}, {"f-number", "aperture"}};

// Exits (when initialised) and frees a camera with fd 0 protected (see fd0_guard.h).
void ReleaseCamera(Camera* camera, GPContext* context, bool initialised) {
  Fd0Guard guard;
  if (initialised) gp_camera_exit(camera, context);  // a camera that is gone fails: fine
  gp_camera_unref(camera);
}

void IgnoreSigpipeIfDefault() {
  struct sigaction current {};
  if (sigaction(SIGPIPE, nullptr, &current) == 0 && current.sa_handler == SIG_DFL) {
    signal(SIGPIPE, SIG_IGN);
  }
}

// Owners for libgphoto2 objects that are only needed inside one call.
struct CameraListOwner {
  CameraList* list = nullptr;
  CameraListOwner() { gp_list_new(&list); }
  ~CameraListOwner() { gp_list_free(list); }
};
struct FileOwner {
  CameraFile* file = nullptr;
  FileOwner() { gp_file_new(&file); }
  ~FileOwner() { gp_file_unref(file); }
};

CameraImage ImageFromFile(CameraFile* file, const std::string& file_name) {
  const char* data = nullptr;
  unsigned long size = 0;
  gp_file_get_data_and_size(file, &data, &size);
  CameraImage image;
  image.data.assign(reinterpret_cast<const uint8_t*>(data),
                    reinterpret_cast<const uint8_t*>(data) + size);
  image.file_name = file_name;
  const char* mime = nullptr;
  if (gp_file_get_mime_type(file, &mime) == GP_OK && mime != nullptr) image.mime_type = mime;
  return image;
}

}  // namespace

GphotoCamera::GphotoCamera(GphotoCameraOptions options) : options_(std::move(options)) {}

GphotoCamera::~GphotoCamera() { Close(); }

std::string GphotoCamera::Describe() const {
  if (!is_open()) {
    return fmt::format("{} on {} (closed)", options_.model.empty() ? "camera" : options_.model,
                       options_.port.empty() ? "an autodetected port" : options_.port);
  }
  return fmt::format("{} on {}", model_, port_);
}

void GphotoCamera::Fail(const std::string& what, int gp_result) const {
  throw MakeGphotoError(Describe(), what, gp_result, log_->diagnostics());
}

void GphotoCamera::RequireOpen(const char* what) const {
  if (!is_open()) {
    throw CameraError(
        CameraError::Kind::kFailed,
        fmt::format("{}: {} needs an open camera; call Open() first", Describe(), what));
  }
}

void GphotoCamera::ResolveAutodetected(std::string& model, std::string& port) {
  if (model.empty() && port.rfind("ptpip:", 0) == 0) model = kPtpIpModel;
  if (!model.empty() && !port.empty()) return;
  CameraListOwner detected;
  const int result = gp_camera_autodetect(detected.list, log_->context());
  if (result < GP_OK) Fail("autodetecting cameras", result);
  std::vector<std::string> seen;
  for (int i = 0; i < gp_list_count(detected.list); ++i) {
    const char* name = nullptr;
    const char* path = nullptr;
    gp_list_get_name(detected.list, i, &name);
    gp_list_get_value(detected.list, i, &path);
    if (name == nullptr || path == nullptr) continue;
    seen.push_back(fmt::format("{} on {}", name, path));
    if ((model.empty() || model == name) && (port.empty() || port == path)) {
      model = name;
      port = path;
      return;
    }
  }
  throw CameraError(CameraError::Kind::kDisconnected,
                    fmt::format("no camera matching model '{}' port '{}' found; autodetected: {}",
                                model.empty() ? "any" : model, port.empty() ? "any" : port,
                                seen.empty() ? "none" : fmt::format("{}", fmt::join(seen, ", "))));
}

void GphotoCamera::Open() {
  if (is_open()) return;
  RequireWritableGphotoHome();
  IgnoreSigpipeIfDefault();
  log_ = std::make_unique<GphotoCallLog>();
  log_->Begin();
  std::string model = options_.model;
  std::string port = NormalizePortPath(options_.port);
  ResolveAutodetected(model, port);
  model_ = model;
  port_ = port;

  EnsureFd0Open();
  Camera* camera = nullptr;
  gp_camera_new(&camera);
  // Any failure from here on must release the half-made camera.
  auto fail = [&](const std::string& what, int result) {
    ReleaseCamera(camera, log_->context(), false);
    Fail(what, result);
  };

  CameraAbilitiesList* abilities_list = nullptr;
  gp_abilities_list_new(&abilities_list);
  int result = gp_abilities_list_load(abilities_list, log_->context());
  const int model_index =
      result < GP_OK ? result : gp_abilities_list_lookup_model(abilities_list, model.c_str());
  CameraAbilities abilities{};
  if (model_index >= GP_OK) {
    gp_abilities_list_get_abilities(abilities_list, model_index, &abilities);
  }
  gp_abilities_list_free(abilities_list);
  if (model_index < GP_OK) {
    ReleaseCamera(camera, log_->context(), false);
    throw CameraError(CameraError::Kind::kFailed,
                      fmt::format("libgphoto2 does not know camera model '{}' ({})", model,
                                  gp_result_as_string(model_index)));
  }
  result = gp_camera_set_abilities(camera, abilities);
  if (result < GP_OK) fail("setting the camera model", result);

  GPPortInfoList* ports = nullptr;
  gp_port_info_list_new(&ports);
  result = gp_port_info_list_load(ports);
  const int port_index =
      result < GP_OK ? result : gp_port_info_list_lookup_path(ports, port.c_str());
  if (port_index >= GP_OK) {
    GPPortInfo info;
    gp_port_info_list_get_info(ports, port_index, &info);
    result = gp_camera_set_port_info(camera, info);  // copies the info
  }
  gp_port_info_list_free(ports);
  if (port_index < GP_OK) {
    ReleaseCamera(camera, log_->context(), false);
    throw CameraError(
        CameraError::Kind::kFailed,
        fmt::format("libgphoto2 has no port '{}' ({})", port, gp_result_as_string(port_index)));
  }
  if (result < GP_OK) fail("setting the port", result);

  {
    Fd0Guard guard;  // a failed init disconnects, which closes fd 0 too
    result = gp_camera_init(camera, log_->context());
  }
  if (result < GP_OK) fail("initialising", result);
  camera_ = camera;
  log::Info("camera: opened {}", Describe());
}

void GphotoCamera::Close() noexcept {
  if (camera_ != nullptr) {
    log_->Begin();
    ReleaseCamera(camera_, log_->context(), true);
    camera_ = nullptr;
  }
  log_.reset();
}

std::vector<std::string> GphotoCamera::ConfigNames(const std::string& name) const {
  std::vector<std::string> names = {name};
  for (const Alias& alias : kAliases) {
    if (name == alias.name) names.emplace_back(alias.alias);
  }
  return names;
}

std::string GphotoCamera::FetchWidget(const std::string& name, CameraWidget** widget) {
  int result = GP_OK;
  for (const std::string& config_name : ConfigNames(name)) {
    log_->Begin();
    result = gp_camera_get_single_config(camera_, config_name.c_str(), widget, log_->context());
    if (result >= GP_OK) return config_name;
    if (result != GP_ERROR_BAD_PARAMETERS && result != GP_ERROR_NOT_SUPPORTED) {
      Fail(fmt::format("reading setting '{}'", name), result);
    }
  }
  // Unknown name: list what the camera does have.
  std::vector<std::string> known;
  CameraListOwner names;
  log_->Begin();
  if (gp_camera_list_config(camera_, names.list, log_->context()) >= GP_OK) {
    for (int i = 0; i < gp_list_count(names.list); ++i) {
      const char* path = nullptr;
      gp_list_get_name(names.list, i, &path);
      if (path == nullptr) continue;
      const char* leaf = std::strrchr(path, '/');
      known.emplace_back(leaf != nullptr ? leaf + 1 : path);
    }
  }
  throw CameraError(CameraError::Kind::kBadSetting,
                    fmt::format("{}: no setting named '{}'; the camera has: {}", Describe(), name,
                                fmt::join(known, ", ")));
}

std::string GphotoCamera::GetSetting(const std::string& name) {
  RequireOpen("GetSetting");
  OwnedWidget widget;
  FetchWidget(name, widget.out());
  return WidgetValueText(widget.get(), name);
}

std::vector<std::string> GphotoCamera::SettingChoices(const std::string& name) {
  RequireOpen("SettingChoices");
  OwnedWidget widget;
  FetchWidget(name, widget.out());
  return WidgetChoices(widget.get());
}

void GphotoCamera::SetSetting(const std::string& name, const std::string& value) {
  RequireOpen("SetSetting");
  OwnedWidget widget;
  const std::string config_name = FetchWidget(name, widget.out());
  SetWidgetValueText(widget.get(), name, value);
  log_->Begin();
  const int result =
      gp_camera_set_single_config(camera_, config_name.c_str(), widget.get(), log_->context());
  if (result == GP_ERROR_BAD_PARAMETERS) {
    throw CameraError(CameraError::Kind::kBadSetting,
                      fmt::format("{}: the camera refused {}='{}'", Describe(), name, value));
  }
  if (result < GP_OK) Fail(fmt::format("setting {}='{}'", name, value), result);
}

CameraImage GphotoCamera::Capture() {
  RequireOpen("Capture");
  log_->Begin();
  CameraFilePath path{};
  int result = gp_camera_capture(camera_, GP_CAPTURE_IMAGE, &path, log_->context());
  if (result < GP_OK) Fail("capture", result);

  FileOwner file;
  log_->Begin();
  result = gp_camera_file_get(camera_, path.folder, path.name, GP_FILE_TYPE_NORMAL, file.file,
                              log_->context());
  if (result < GP_OK) Fail(fmt::format("downloading {}/{}", path.folder, path.name), result);
  CameraImage image = ImageFromFile(file.file, path.name);

  // The image is safe with us; a card that keeps it only fills up, so a failed delete is a
  // warning and the next call reports a real fault.
  log_->Begin();
  result = gp_camera_file_delete(camera_, path.folder, path.name, log_->context());
  if (result < GP_OK) {
    log::Warn("camera: deleting {}/{} from {} failed: {}", path.folder, path.name, Describe(),
              gp_result_as_string(result));
  }
  DrainEvents();
  return image;
}

void GphotoCamera::DrainEvents() {
  for (int i = 0; i < kMaxDrainedEvents; ++i) {
    CameraEventType type = GP_EVENT_TIMEOUT;
    void* data = nullptr;
    log_->Begin();
    const int result =
        gp_camera_wait_for_event(camera_, kDrainWaitMs, &type, &data, log_->context());
    if (result < GP_OK) {
      std::free(data);
      Fail("draining camera events", result);
    }
    if (type == GP_EVENT_FILE_ADDED && data != nullptr) {
      // A second file of the same shot (RAW + JPEG): keep the card empty.
      const auto* extra = static_cast<CameraFilePath*>(data);
      log::Warn("camera: {} stored an extra file {}/{}; deleting it", Describe(), extra->folder,
                extra->name);
      gp_camera_file_delete(camera_, extra->folder, extra->name, log_->context());
    }
    std::free(data);  // CameraFilePath or text, malloc'd by libgphoto2; nullptr otherwise
    if (type == GP_EVENT_TIMEOUT) return;
  }
}

CameraImage GphotoCamera::Preview() {
  RequireOpen("Preview");
  FileOwner file;
  log_->Begin();
  const int result = gp_camera_capture_preview(camera_, file.file, log_->context());
  if (result == GP_ERROR_NOT_SUPPORTED) {
    throw CameraError(CameraError::Kind::kUnsupported,
                      fmt::format("{}: no live view (libgphoto2 cannot capture a preview from "
                                  "this camera)",
                                  Describe()));
  }
  if (result < GP_OK) Fail("live-view preview", result);
  const char* name = nullptr;
  gp_file_get_name(file.file, &name);
  return ImageFromFile(file.file, name != nullptr && *name != '\0' ? name : "preview.jpg");
}

std::vector<DetectedCamera> ListCameras() {
  GphotoCallLog log;
  log.Begin();
  CameraListOwner detected;
  const int result = gp_camera_autodetect(detected.list, log.context());
  if (result < GP_OK) {
    throw MakeGphotoError("libgphoto2", "autodetecting cameras", result, log.diagnostics());
  }
  std::vector<DetectedCamera> cameras;
  for (int i = 0; i < gp_list_count(detected.list); ++i) {
    const char* name = nullptr;
    const char* path = nullptr;
    gp_list_get_name(detected.list, i, &name);
    gp_list_get_value(detected.list, i, &path);
    if (name != nullptr && path != nullptr) cameras.push_back({name, path});
  }
  return cameras;
}

}  // namespace avc::camera_driver
