#pragma once

// avc-camera on the bus: answers CAPTURE_REQUEST with ack_t (ACCEPTED or REFUSED, then DONE once
// the image product was acknowledged by its receivers, or FAILED with the reason) and sends each
// picture as an image_t product on PRODUCT/IMAGE (PRODUCT/PREVIEW for live-view frames).
//  - The backend runs on a CameraWorker thread; the bus loop never blocks on the camera.
//  - A busy camera is retried with a doubling pause; a lost camera fails the running request,
//    puts the heartbeat in ERROR and is re-opened with exponential backoff (at once when USB
//    hot-plug sees a known body arrive).
//  - Heartbeat: READY idle, BUSY capturing, ERROR while the camera is not usable.
//  - A repeated request_id gets its last answer again and never takes a second picture.

#include <avc/capture_request_t.hpp>
#include <chrono>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "core/bus/ack_book.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/products/product_sender.h"
#include "drivers/camera/camera_backend.h"
#include "drivers/camera/camera_worker.h"
#include "drivers/usb/usb_devices.h"

namespace avc::camera_driver {

struct CameraNodeOptions {
  std::string service = "avc-camera";
  std::string camera_id = "cam0";
  int busy_retries = 5;                          // attempts after the first busy answer
  std::chrono::milliseconds busy_backoff{200};   // first pause; doubles per retry
  std::chrono::milliseconds reconnect_min{250};  // backoff between re-open attempts
  std::chrono::milliseconds reconnect_max{5000};
  size_t max_queued_captures = 4;  // further requests are refused until the queue drains
  bool watch_usb = false;          // react to hot-plug of drivers/camera/known_cameras.h bodies
  products::SenderOptions products;

  std::string Validate() const;
};

class CameraNode {
 public:
  // Subscribes and starts opening the camera at once. Throws std::invalid_argument for bad
  // options.
  CameraNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
             std::unique_ptr<CameraBackend> backend, CameraNodeOptions options);
  ~CameraNode();
  CameraNode(const CameraNode&) = delete;
  CameraNode& operator=(const CameraNode&) = delete;

  // Before the process ends: requests not yet answered are FAILED.
  void Shutdown();

  bool connected() const { return connected_; }
  int64_t captures_delivered() const { return captures_delivered_; }

 private:
  struct Outcome;

  void OnRequest(const avc::capture_request_t& request);
  // Why the request is refused for good (malformed), or "".
  std::string Validate(const avc::capture_request_t& request) const;
  // Why no capture can be taken now (stopping, no camera, queue full), or "": NOT_READY.
  std::string NotReady() const;
  void Tick();
  void TryConnect();
  void OnConnected(const std::string& description);
  void OnConnectFailed(const std::string& error);
  void LoseCamera(const std::string& why);
  void OnCaptured(Outcome outcome);
  void OnUsb(usb::UsbDeviceWatcher::Event event, const usb::UsbDevice& device);
  // The final answer to an accepted request (once: later answers for it are dropped).
  void Finish(const std::string& request_id, int8_t status, const std::string& reason);
  void UpdateHeartbeat();
  // Runs fn on the loop thread later, unless the node is gone by then.
  void PostToLoop(std::function<void()> fn);

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  bus::HeartbeatPublisher& heartbeat_;
  CameraNodeOptions options_;
  bus::AckBook acks_;
  products::ProductSender sender_;

  bool connected_ = false;
  bool connecting_ = false;
  std::string description_;
  std::string error_;
  std::chrono::milliseconds reconnect_delay_;
  int64_t next_connect_us_ = 0;
  std::set<std::string> unanswered_;  // accepted, not yet answered DONE/FAILED
  int64_t captures_delivered_ = 0;
  bool shutting_down_ = false;

  bus::Bus::SubscriptionId subscription_ = 0;
  bus::EventLoop::TimerId timer_ = 0;
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);
  std::unique_ptr<usb::UsbDeviceWatcher> usb_;
  // Last: destroyed first, so no job outlives what it refers to.
  std::unique_ptr<CameraWorker> worker_;
};

}  // namespace avc::camera_driver
