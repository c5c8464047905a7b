#pragma once

// Drives a cell over the bus from one program (the calibrator, benchmarks, tests; the
// orchestrator will do the same): a command, then its ack; a capture request, then the image
// product. Every call runs the event loop until the answer comes and times it; a refusal, a
// failure or a timeout throws with the service's reason. A request is re-sent every second until
// it is done: that covers lost datagrams and a driver restarted meanwhile (a repeated request id
// never repeats work).
// Request ids carry a per-client session tag: drivers answer a repeated id from memory, so a
// restarted program counting from 1 again must not reuse the ids of its previous life.
// Robot and turntable commands are signed with the cell's key (core/auth) when the client has
// one; every re-send is signed anew.

#include <Eigen/Geometry>
#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/image_t.hpp>
#include <avc/robot_command_t.hpp>
#include <avc/turntable_command_t.hpp>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/auth/command_auth.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/plant_keep_out.h"
#include "core/products/product_receiver.h"

namespace avc::client {

// A command the service refused for good (unreachable target, outside the safety envelope, bad
// value): the cell is fine, the request was not. Other failures (timeouts, FAILED) are plain
// std::runtime_error. A driver that is not ready (starting, reconnecting, busy: NOT_READY) never
// causes one: the command waits for it (SendUntilDone).
class CommandRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CapturedView {
  avc::image_t image;
  double request_to_sent_s = 0;   // camera side: settings, exposure, render, download, packaging
  double sent_to_received_s = 0;  // the product over the bulk bus
  double request_to_done_s = 0;   // until the camera's DONE (product acknowledged)
};

class CellClient {
 public:
  // `name` starts every request id and names this client as a product consumer. Motion
  // commands are signed with `key`, else with the cell's key at auth::DefaultKeyFile(cell) when
  // that file exists (else they go unsigned, which only a cell allowing that obeys). Throws
  // auth::KeyError for a key file that exists but is unusable.
  CellClient(bus::Bus& bus, bus::EventLoop& loop, std::string name = "avc-bench",
             std::optional<auth::CommandKey> key = std::nullopt);
  ~CellClient();
  CellClient(const CellClient&) = delete;
  CellClient& operator=(const CellClient&) = delete;

  // Runs the loop until every service reports READY. Throws std::runtime_error naming the ones
  // that did not, with their last heartbeat detail.
  void WaitReady(const std::vector<std::string>& services, std::chrono::milliseconds timeout);

  // Each returns the seconds from sending to DONE.
  double MoveJoints(const kinematics::JointVector& q, std::chrono::milliseconds timeout);
  double Robot(int8_t kind, std::chrono::milliseconds timeout);  // power, brakes, ...
  // The plant's space the arm must stay out of (an empty one clears it).
  double SetPlantKeepOut(const kinematics::PlantKeepOut& keep_out,
                         std::chrono::milliseconds timeout);
  double TurntableGoto(double angle_rad, std::chrono::milliseconds timeout);
  CapturedView Capture(const std::string& image_id, int8_t encoding,
                       std::chrono::milliseconds timeout);

  // Joints and flange pose of the last ROBOT_STATE (zeros / identity before one arrived).
  kinematics::JointVector last_joints() const { return last_joints_; }
  Eigen::Isometry3d last_flange_pose() const { return last_flange_pose_; }
  // Angle of the last TURNTABLE_STATE, radians.
  double last_table_angle() const { return last_table_angle_; }
  // Runs the loop until a ROBOT_STATE and TURNTABLE_STATE newer than now have arrived (what was
  // read after a motion ended, not before).
  void WaitFreshState(std::chrono::milliseconds timeout);

 private:
  std::string NextId(const std::string& what);
  // Signs (when there is a key) and publishes a robot or turntable command.
  template <class Command>
  void PublishCommand(std::string_view channel, Command& command) {
    if (signer_) signer_->Sign(command, bus_.FullChannel(channel));
    bus_.Publish(channel, command);
  }
  // Publishes with `send` until the service acknowledges `id` at all (a datagram can be lost;
  // re-sending an id is harmless), then runs the loop until it is DONE. A NOT_READY answer
  // (a driver restarted mid-scan, say) sends the same id again once the service heartbeats
  // READY anew. Returns the seconds from the first send.
  double SendUntilDone(const std::string& id, const std::function<void()>& send,
                       std::chrono::milliseconds timeout);
  // Runs the loop until `service` heartbeats READY after now; false when `timeout` passed.
  bool WaitReadyAgain(const std::string& service, std::chrono::milliseconds timeout);

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  std::optional<auth::CommandSigner> signer_;
  std::vector<bus::Bus::SubscriptionId> subscriptions_;
  std::unique_ptr<products::ProductReceiver> receiver_;
  std::string id_prefix_;                         // name-session-
  std::map<std::string, avc::ack_t> final_acks_;  // by request id: DONE, FAILED or REFUSED
  std::map<std::string, avc::heartbeat_t> health_;
  std::map<std::string, int64_t> heartbeats_heard_;                        // by service
  std::map<std::string, std::pair<products::Product, int64_t>> products_;  // by name; rx time
  kinematics::JointVector last_joints_ = kinematics::JointVector::Zero();
  Eigen::Isometry3d last_flange_pose_ = Eigen::Isometry3d::Identity();
  double last_table_angle_ = 0;
  int64_t robot_states_ = 0;
  int64_t table_states_ = 0;
  int next_id_ = 1;
};

}  // namespace avc::client
