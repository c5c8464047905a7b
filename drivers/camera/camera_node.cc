#include "drivers/camera/camera_node.h"

#include <fmt/format.h>

#include <avc/image_t.hpp>
#include <thread>
#include <utility>

#include "core/bus/channels.h"
#include "core/util/clock.h"
#include "core/util/log.h"
#include "drivers/camera/image_packaging.h"
#include "drivers/camera/known_cameras.h"

namespace avc::camera_driver {

// What a capture job hands back to the loop thread.
struct CameraNode::Outcome {
  avc::capture_request_t request;
  std::optional<avc::image_t> image;
  std::optional<CameraError::Kind> error_kind;
  std::string error;
  int busy_answers = 0;
  double camera_seconds = 0;  // settings + exposure + download + packaging
};

namespace {

std::string SafeImageIdProblem(const std::string& id) {
  if (id.empty()) return "empty image_id";
  if (id.size() > 128) return fmt::format("image_id of {} characters (max 128)", id.size());
  for (const char c : id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok || id == "." || id == "..") {
      return fmt::format("image_id '{}' may only use letters, digits, '_', '-' and '.'", id);
    }
  }
  return "";
}

void ApplyRequestedSettings(CameraBackend& camera, const avc::capture_request_t& request) {
  const std::pair<const char*, const std::string*> wanted[] = {
      {"iso", &request.iso},
      {"shutterspeed", &request.shutterspeed},
      {"aperture", &request.aperture}};
  for (const auto& [name, value] : wanted) {
    if (!value->empty() && camera.GetSetting(name) != *value) camera.SetSetting(name, *value);
  }
}

// Reads a setting for the image's metadata; a camera without it leaves the field unknown.
std::string SettingOrEmpty(CameraBackend& camera, const char* name) {
  try {
    return camera.GetSetting(name);
  } catch (const CameraError&) {
    return "";
  }
}

CameraImage TakePicture(CameraBackend& camera, bool preview, const CameraNodeOptions& options,
                        int* busy_answers) {
  std::chrono::milliseconds pause = options.busy_backoff;
  for (int attempt = 0;; ++attempt) {
    try {
      return preview ? camera.Preview() : camera.Capture();
    } catch (const CameraError& error) {
      if (error.kind() != CameraError::Kind::kBusy || attempt >= options.busy_retries) throw;
      ++*busy_answers;
      log::Warn("camera busy ({}); retry {} of {} in {} ms", error.what(), attempt + 1,
                options.busy_retries, pause.count());
      std::this_thread::sleep_for(pause);
      pause *= 2;
    }
  }
}

}  // namespace

std::string CameraNodeOptions::Validate() const {
  if (camera_id.empty()) return "empty camera id";
  if (busy_retries < 0) return "busy retries must be >= 0";
  if (busy_backoff.count() < 0) return "busy backoff must be >= 0 ms";
  if (reconnect_min.count() <= 0 || reconnect_max < reconnect_min) {
    return "reconnect backoff must satisfy 0 < min <= max";
  }
  if (max_queued_captures < 1) return "the capture queue must hold at least one request";
  return products.Validate();
}

CameraNode::CameraNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
                       std::unique_ptr<CameraBackend> backend, CameraNodeOptions options)
    : bus_(bus),
      loop_(loop),
      heartbeat_(heartbeat),
      options_(std::move(options)),
      acks_(bus, options_.service),
      sender_(bus, loop, options_.products),
      reconnect_delay_(options_.reconnect_min) {
  const std::string problem = options_.Validate();
  if (!problem.empty()) throw std::invalid_argument("avc-camera: " + problem);
  if (!backend) throw std::invalid_argument("avc-camera: no camera backend");
  worker_ = std::make_unique<CameraWorker>(std::move(backend));
  subscription_ = bus_.Subscribe<avc::capture_request_t>(
      channels::kCaptureRequest,
      [this](const avc::capture_request_t& request, const bus::RxInfo&) { OnRequest(request); });
  if (options_.watch_usb) {
    try {
      usb_ = std::make_unique<usb::UsbDeviceWatcher>(KnownCameraBodies());
      const bool hotplug =
          usb_->Watch([this](usb::UsbDeviceWatcher::Event event, const usb::UsbDevice& device) {
            PostToLoop([this, event, device] { OnUsb(event, device); });
          });
      log::Info("watching USB for camera bodies ({})", hotplug ? "libusb hot-plug" : "polling");
    } catch (const usb::UsbError& error) {
      log::Warn("no USB hot-plug for the camera ({}); relying on reconnect attempts", error.what());
    }
  }
  error_ = "opening the camera";
  TryConnect();
  UpdateHeartbeat();
  timer_ = loop_.AddTimer(
      std::chrono::milliseconds(100), [this] { Tick(); }, /*repeating=*/true);
}

CameraNode::~CameraNode() {
  loop_.CancelTimer(timer_);
  bus_.Unsubscribe(subscription_);
  if (usb_) usb_->StopWatching();
}

void CameraNode::PostToLoop(std::function<void()> fn) {
  loop_.Post([alive = std::weak_ptr<int>(alive_), fn = std::move(fn)] {
    if (!alive.expired()) fn();
  });
}

void CameraNode::Tick() {
  if (!connected_ && !connecting_ && MonotonicMicros() >= next_connect_us_) TryConnect();
  UpdateHeartbeat();
}

void CameraNode::TryConnect() {
  connecting_ = true;
  worker_->Submit([this](CameraBackend& camera) {
    try {
      camera.Close();
      camera.Open();
      PostToLoop([this, description = camera.Describe()] { OnConnected(description); });
    } catch (const std::exception& error) {
      camera.Close();
      PostToLoop([this, what = std::string(error.what())] { OnConnectFailed(what); });
    }
  });
}

void CameraNode::OnConnected(const std::string& description) {
  connecting_ = false;
  connected_ = true;
  description_ = description;
  error_.clear();
  reconnect_delay_ = options_.reconnect_min;
  log::Info("camera ready: {}", description_);
  UpdateHeartbeat();
}

void CameraNode::OnConnectFailed(const std::string& error) {
  connecting_ = false;
  error_ =
      fmt::format("cannot open the camera: {} (retry in {} ms)", error, reconnect_delay_.count());
  log::Warn("{}", error_);
  next_connect_us_ = MonotonicMicros() + reconnect_delay_.count() * 1000;
  reconnect_delay_ = std::min(reconnect_delay_ * 2, options_.reconnect_max);
  UpdateHeartbeat();
}

void CameraNode::LoseCamera(const std::string& why) {
  if (!connected_) return;
  connected_ = false;
  error_ = "camera lost: " + why;
  log::Error("{}", error_);
  worker_->Submit([](CameraBackend& camera) { camera.Close(); });
  next_connect_us_ = MonotonicMicros() + reconnect_delay_.count() * 1000;
  UpdateHeartbeat();
}

void CameraNode::OnUsb(usb::UsbDeviceWatcher::Event event, const usb::UsbDevice& device) {
  if (event == usb::UsbDeviceWatcher::Event::kLeft) {
    LoseCamera("unplugged: " + device.Describe());
  } else if (!connected_) {
    log::Info("camera plugged in: {}; opening it now", device.Describe());
    reconnect_delay_ = options_.reconnect_min;
    next_connect_us_ = 0;
    if (!connecting_) TryConnect();
  }
}

std::string CameraNode::Validate(const avc::capture_request_t& request) const {
  if (request.request_id.empty()) return "empty request_id";
  if (const std::string problem = SafeImageIdProblem(request.image_id); !problem.empty()) {
    return problem;
  }
  if (request.encoding != avc::image_t::ENCODING_RAW &&
      request.encoding != avc::image_t::ENCODING_PNG &&
      request.encoding != avc::image_t::ENCODING_JPEG) {
    return fmt::format("unknown encoding {}", request.encoding);
  }
  return "";
}

std::string CameraNode::NotReady() const {
  if (shutting_down_) return options_.service + " is stopping";
  if (!connected_) return "camera not ready: " + error_;
  if (unanswered_.size() >= options_.max_queued_captures) {
    return fmt::format("busy: {} captures already queued", unanswered_.size());
  }
  return "";
}

void CameraNode::OnRequest(const avc::capture_request_t& request) {
  if (acks_.Repeat(request.request_id)) return;  // answered before: never a second picture
  const std::string refusal = Validate(request);
  if (!refusal.empty()) {
    log::Warn("camera: refused '{}': {}", request.request_id, refusal);
    acks_.Send(request.request_id, avc::ack_t::STATUS_REFUSED, refusal);
    return;
  }
  if (const std::string not_ready = NotReady(); !not_ready.empty()) {
    log::Warn("camera: not ready for '{}': {}", request.request_id, not_ready);
    acks_.SendNotReady(request.request_id, not_ready);
    return;
  }
  unanswered_.insert(request.request_id);
  acks_.Send(request.request_id, avc::ack_t::STATUS_ACCEPTED,
             request.preview ? "preview" : "capture " + request.image_id);
  UpdateHeartbeat();
  worker_->Submit([this, request, options = options_](CameraBackend& camera) {
    Outcome outcome;
    outcome.request = request;
    const int64_t start_us = MonotonicMicros();
    try {
      ApplyRequestedSettings(camera, request);
      const CameraImage picture =
          TakePicture(camera, request.preview, options, &outcome.busy_answers);
      ImageLabels labels;
      labels.image_id = request.image_id;
      labels.camera_id = options.camera_id;
      labels.encoding = request.encoding;
      labels.exposure_us = ShutterMicros(SettingOrEmpty(camera, "shutterspeed"));
      labels.iso = std::atof(SettingOrEmpty(camera, "iso").c_str());
      outcome.image = PackageImage(picture, labels);
    } catch (const CameraError& error) {
      outcome.error_kind = error.kind();
      outcome.error = error.what();
    } catch (const std::exception& error) {
      outcome.error_kind = CameraError::Kind::kFailed;
      outcome.error = error.what();
    }
    outcome.camera_seconds = (MonotonicMicros() - start_us) * 1e-6;
    PostToLoop([this, outcome = std::move(outcome)]() mutable { OnCaptured(std::move(outcome)); });
  });
}

void CameraNode::OnCaptured(Outcome outcome) {
  const std::string id = outcome.request.request_id;
  if (!outcome.image) {
    const std::string reason =
        fmt::format("{} ({})", outcome.error, CameraErrorKindName(*outcome.error_kind));
    log::Warn("camera: '{}' failed: {}", id, reason);
    Finish(id, avc::ack_t::STATUS_FAILED, reason);
    if (*outcome.error_kind == CameraError::Kind::kDisconnected) LoseCamera(outcome.error);
    return;
  }
  avc::image_t& image = *outcome.image;
  const bool preview = outcome.request.preview;
  const std::string name = ProductName(preview ? "previews" : "images", image);
  const std::string summary =
      fmt::format("{} {}x{} {} bytes, camera {:.2f} s{}", name, image.width, image.height,
                  image.size, outcome.camera_seconds,
                  outcome.busy_answers > 0 ? fmt::format(", {} busy retries", outcome.busy_answers)
                                           : std::string());
  sender_.SendMessage(preview ? channels::kProductPreview : channels::kProductImage, name, image,
                      [this, id, summary](const products::SendResult& result) {
                        if (result.ok) ++captures_delivered_;
                        Finish(id, result.ok ? avc::ack_t::STATUS_DONE : avc::ack_t::STATUS_FAILED,
                               result.ok ? summary : result.error);
                      });
}

void CameraNode::Finish(const std::string& request_id, int8_t status, const std::string& reason) {
  if (unanswered_.erase(request_id) == 0) return;
  acks_.Send(request_id, status, reason);
  UpdateHeartbeat();
}

void CameraNode::UpdateHeartbeat() {
  if (!connected_) {
    heartbeat_.Set(bus::ServiceState::kError, error_);
  } else if (!unanswered_.empty()) {
    heartbeat_.Set(bus::ServiceState::kBusy,
                   fmt::format("{} capture(s) in flight", unanswered_.size()));
  } else {
    heartbeat_.Set(bus::ServiceState::kReady, description_);
  }
}

void CameraNode::Shutdown() {
  shutting_down_ = true;
  const std::set<std::string> unanswered = unanswered_;
  for (const std::string& id : unanswered) {
    Finish(id, avc::ack_t::STATUS_FAILED, options_.service + " stopping");
  }
}

}  // namespace avc::camera_driver
