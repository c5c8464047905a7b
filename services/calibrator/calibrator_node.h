#pragma once

// avc-calibrator on the bus: serves one cell calibration.
//  - CALIBRATION: the calibration (yaml text) at start and every `republish_period`.
//  - CAMERA: the camera of every image. When a (non-preview) CAPTURE_REQUEST goes out, the arm
//    and table are still (the orchestrator captures only then), so the latest ROBOT_STATE flange
//    pose and TURNTABLE_STATE angle give the camera of that image_id. A request that comes while
//    either is moving or unknown gets no camera and a warning: its pose would be a guess.
//  - CAMERA_QUERY: the camera for any joint vector or flange pose and table angle, answered on
//    CAMERA with image_id = request_id; bad queries get a REFUSED ack with the reason.
// Heartbeat: READY; its detail says where the calibration came from and, until both states
// arrived, that images cannot be posed yet.

#include <avc/camera_query_t.hpp>
#include <avc/capture_request_t.hpp>
#include <avc/robot_state_t.hpp>
#include <avc/turntable_state_t.hpp>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "core/bus/ack_book.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/calibration/cell/cell_calibration.h"

namespace avc::calibrator {

struct CalibratorNodeOptions {
  std::string service = "avc-calibrator";
  std::string camera_id = "cam0";
  std::string source;  // where the calibration came from, for CALIBRATION
  std::chrono::milliseconds republish_period{5000};
};

class CalibratorNode {
 public:
  // Throws std::invalid_argument for an invalid calibration.
  CalibratorNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
                 calibration::CellCalibration calibration, CalibratorNodeOptions options);
  ~CalibratorNode();
  CalibratorNode(const CalibratorNode&) = delete;
  CalibratorNode& operator=(const CalibratorNode&) = delete;

  int64_t cameras_published() const { return cameras_published_; }

 private:
  void OnCapture(const avc::capture_request_t& request);
  void OnQuery(const avc::camera_query_t& query);
  void PublishCamera(const std::string& image_id, const camera::Camera& camera);
  void PublishCalibration();
  void UpdateHeartbeat();

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  bus::HeartbeatPublisher& heartbeat_;
  calibration::CellCalibration calibration_;
  CalibratorNodeOptions options_;
  bus::AckBook acks_;
  std::string yaml_;
  std::optional<avc::robot_state_t> robot_;
  std::optional<avc::turntable_state_t> table_;
  int64_t cameras_published_ = 0;
  std::vector<bus::Bus::SubscriptionId> subscriptions_;
  bus::EventLoop::TimerId timer_ = 0;
};

}  // namespace avc::calibrator
