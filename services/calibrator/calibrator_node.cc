#include "services/calibrator/calibrator_node.h"

#include <fmt/format.h>

#include <avc/calibration_t.hpp>
#include <avc/camera_t.hpp>
#include <cmath>

#include "core/bus/channels.h"
#include "core/calibration/cell/calibration_yaml.h"
#include "core/messages/camera_message.h"
#include "core/util/log.h"
#include "core/util/sha256.h"

namespace avc::calibrator {
namespace {

Eigen::Isometry3d FromRowMajor(const double* values) {
  Eigen::Isometry3d pose;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) pose.matrix()(r, c) = values[4 * r + c];
  }
  return pose;
}

}  // namespace

CalibratorNode::CalibratorNode(bus::Bus& bus, bus::EventLoop& loop,
                               bus::HeartbeatPublisher& heartbeat,
                               calibration::CellCalibration calibration,
                               CalibratorNodeOptions options)
    : bus_(bus),
      loop_(loop),
      heartbeat_(heartbeat),
      calibration_(std::move(calibration)),
      options_(std::move(options)),
      acks_(bus, options_.service) {
  if (const std::string problem = calibration_.Validate(); !problem.empty()) {
    throw std::invalid_argument("avc-calibrator: calibration: " + problem);
  }
  yaml_ = calibration::CalibrationToYaml(calibration_);
  subscriptions_.push_back(bus_.Subscribe<avc::robot_state_t>(
      channels::kRobotState, [this](const avc::robot_state_t& state, const bus::RxInfo&) {
        robot_ = state;
        UpdateHeartbeat();
      }));
  subscriptions_.push_back(bus_.Subscribe<avc::turntable_state_t>(
      channels::kTurntableState, [this](const avc::turntable_state_t& state, const bus::RxInfo&) {
        table_ = state;
        UpdateHeartbeat();
      }));
  subscriptions_.push_back(bus_.Subscribe<avc::capture_request_t>(
      channels::kCaptureRequest,
      [this](const avc::capture_request_t& request, const bus::RxInfo&) { OnCapture(request); }));
  subscriptions_.push_back(bus_.Subscribe<avc::camera_query_t>(
      channels::kCameraQuery,
      [this](const avc::camera_query_t& query, const bus::RxInfo&) { OnQuery(query); }));
  PublishCalibration();
  UpdateHeartbeat();
  timer_ = loop_.AddTimer(
      options_.republish_period, [this] { PublishCalibration(); }, /*repeating=*/true);
}

CalibratorNode::~CalibratorNode() {
  loop_.CancelTimer(timer_);
  for (const auto id : subscriptions_) bus_.Unsubscribe(id);
}

void CalibratorNode::PublishCalibration() {
  avc::calibration_t message{};
  message.format_version = calibration::CellCalibration::kFormatVersion;
  message.source = options_.source;
  message.sha256 = Sha256Hex(yaml_);
  message.yaml = yaml_;
  bus_.Publish(channels::kCalibration, message);
}

void CalibratorNode::PublishCamera(const std::string& image_id, const camera::Camera& camera) {
  avc::camera_t message = messages::CameraToMessage(camera, image_id, options_.camera_id);
  bus_.Publish(channels::kCamera, message);
  ++cameras_published_;
}

void CalibratorNode::OnCapture(const avc::capture_request_t& request) {
  if (request.preview || request.image_id.empty()) return;
  if (!robot_ || !table_) {
    log::Warn("no camera for image '{}': no {} state yet", request.image_id,
              !robot_ ? "robot" : "turntable");
    return;
  }
  if (robot_->moving || table_->moving) {
    log::Warn("no camera for image '{}': the {} is moving", request.image_id,
              robot_->moving ? "arm" : "table");
    return;
  }
  PublishCamera(request.image_id,
                calibration_.CameraAt(FromRowMajor(robot_->T_base_flange), table_->angle));
}

void CalibratorNode::OnQuery(const avc::camera_query_t& query) {
  if (acks_.Repeat(query.request_id)) return;
  try {
    if (query.request_id.empty()) throw std::invalid_argument("empty request_id");
    camera::Camera camera;
    if (query.kind == avc::camera_query_t::KIND_JOINTS) {
      camera = calibration_.CameraAtJoints(Eigen::Map<const kinematics::JointVector>(query.q),
                                           query.table_angle);
    } else if (query.kind == avc::camera_query_t::KIND_FLANGE) {
      camera = calibration_.CameraAt(FromRowMajor(query.T_base_flange), query.table_angle);
    } else {
      throw std::invalid_argument(fmt::format("unknown query kind {}", query.kind));
    }
    PublishCamera(query.request_id, camera);
    acks_.Send(query.request_id, avc::ack_t::STATUS_DONE, "answered on CAMERA");
  } catch (const std::invalid_argument& error) {
    acks_.Send(query.request_id, avc::ack_t::STATUS_REFUSED, error.what());
  }
}

void CalibratorNode::UpdateHeartbeat() {
  if (!robot_ || !table_) {
    heartbeat_.Set(bus::ServiceState::kReady,
                   fmt::format("calibration from {}; waiting for {} state to pose images",
                               options_.source, !robot_ ? "robot" : "turntable"));
  } else {
    heartbeat_.Set(bus::ServiceState::kReady, fmt::format("calibration from {}", options_.source));
  }
}

}  // namespace avc::calibrator
