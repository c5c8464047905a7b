#include "drivers/client/cell_client.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <avc/capture_request_t.hpp>
#include <avc/robot_state_t.hpp>
#include <avc/turntable_state_t.hpp>
#include <stdexcept>
#include <utility>

#include "core/bus/channels.h"
#include "core/bus/heartbeat.h"
#include "core/kinematics/row_major_pose.h"
#include "core/util/clock.h"
#include "core/util/session_tag.h"

namespace avc::client {
namespace {

int64_t WallMicros() { return SystemClock().NowMicros(); }

constexpr std::chrono::milliseconds kImageAfterDoneGrace{10000};

}  // namespace

CellClient::CellClient(bus::Bus& bus, bus::EventLoop& loop, std::string name,
                       std::optional<auth::CommandKey> key)
    : bus_(bus), loop_(loop), id_prefix_(fmt::format("{}-{}-", name, SessionTag())) {
  if (!key) key = auth::FindCommandKey(bus_.cell());
  if (key) signer_.emplace(std::move(*key), bus_.options().source, bus_.cell());
  subscriptions_.push_back(
      bus_.Subscribe<avc::ack_t>(channels::kAck, [this](const avc::ack_t& ack, const bus::RxInfo&) {
        if (ack.status != avc::ack_t::STATUS_ACCEPTED) final_acks_[ack.request_id] = ack;
      }));
  subscriptions_.push_back(bus_.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [this](const avc::heartbeat_t& beat, const bus::RxInfo&) {
        health_[beat.service] = beat;
        ++heartbeats_heard_[beat.service];
      }));
  subscriptions_.push_back(bus_.Subscribe<avc::robot_state_t>(
      channels::kRobotState, [this](const avc::robot_state_t& state, const bus::RxInfo&) {
        for (int i = 0; i < 6; ++i) last_joints_[i] = state.q[i];
        last_flange_pose_ = kinematics::IsometryFromRowMajor(state.T_base_flange);
        ++robot_states_;
      }));
  subscriptions_.push_back(bus_.Subscribe<avc::turntable_state_t>(
      channels::kTurntableState, [this](const avc::turntable_state_t& state, const bus::RxInfo&) {
        last_table_angle_ = state.angle;
        ++table_states_;
      }));
  receiver_ = std::make_unique<products::ProductReceiver>(
      bus_, name, "PRODUCT/IMAGE", [this](const products::Product& product, const bus::RxInfo&) {
        products_[product.name] = {product, WallMicros()};
      });
}

CellClient::~CellClient() {
  for (const auto id : subscriptions_) bus_.Unsubscribe(id);
}

void CellClient::WaitReady(const std::vector<std::string>& services,
                           std::chrono::milliseconds timeout) {
  const auto all_ready = [&] {
    for (const std::string& service : services) {
      const auto it = health_.find(service);
      if (it == health_.end() || it->second.state != avc::heartbeat_t::STATE_READY) return false;
    }
    return true;
  };
  if (loop_.RunUntil(all_ready, timeout)) return;
  std::string missing;
  for (const std::string& service : services) {
    const auto it = health_.find(service);
    missing += it == health_.end()
                   ? fmt::format("\n  {}: never heard", service)
                   : fmt::format("\n  {}: {} {}", service, bus::ServiceStateName(it->second.state),
                                 it->second.detail);
  }
  throw std::runtime_error("services not ready after " + std::to_string(timeout.count()) +
                           " ms:" + missing);
}

void CellClient::WaitFreshState(std::chrono::milliseconds timeout) {
  const int64_t robot_before = robot_states_, table_before = table_states_;
  if (!loop_.RunUntil(
          [&] { return robot_states_ > robot_before + 1 && table_states_ > table_before + 1; },
          timeout)) {
    throw std::runtime_error("no fresh ROBOT_STATE and TURNTABLE_STATE within " +
                             std::to_string(timeout.count()) + " ms");
  }
}

bool CellClient::WaitReadyAgain(const std::string& service, std::chrono::milliseconds timeout) {
  const int64_t heard_before = heartbeats_heard_[service];
  return loop_.RunUntil(
      [&] {
        return heartbeats_heard_[service] > heard_before &&
               health_[service].state == avc::heartbeat_t::STATE_READY;
      },
      timeout);
}

std::string CellClient::NextId(const std::string& what) {
  return fmt::format("{}{}-{}", id_prefix_, what, next_id_++);
}

double CellClient::SendUntilDone(const std::string& id, const std::function<void()>& send,
                                 std::chrono::milliseconds timeout) {
  const int64_t sent_us = MonotonicMicros();
  // Sent again every second until the final answer: that covers a lost datagram, and a driver
  // restarted while the command ran, which has forgotten it and takes it up (a live driver
  // answers a repeated id from memory and does nothing twice).
  const int64_t deadline_us = sent_us + static_cast<int64_t>(timeout.count()) * 1000;
  const auto remaining_ms = [&] {
    return std::chrono::milliseconds(
        std::max<int64_t>((deadline_us - MonotonicMicros()) / 1000, 0));
  };
  send();
  for (;;) {
    while (!loop_.RunUntil([&] { return final_acks_.count(id) != 0; },
                           std::min(remaining_ms(), std::chrono::milliseconds(1000)))) {
      if (loop_.quitting()) {  // SIGTERM: the caller pauses; a resume sends the command again
        throw std::runtime_error(fmt::format("stopped before '{}' was answered", id));
      }
      if (MonotonicMicros() >= deadline_us) {
        throw std::runtime_error(
            fmt::format("no answer to '{}' within {} ms", id, timeout.count()));
      }
      send();
    }
    const avc::ack_t& ack = final_acks_.at(id);
    if (ack.status != avc::ack_t::STATUS_NOT_READY) break;
    // A driver starting, reconnecting or busy (e.g. restarted mid-scan) takes the same request
    // once its heartbeat says READY.
    const avc::ack_t not_ready = ack;
    final_acks_.erase(id);
    if (!WaitReadyAgain(not_ready.service, remaining_ms())) {
      throw std::runtime_error(fmt::format("{} was not ready for '{}' within {} ms: {}",
                                           not_ready.service, id, timeout.count(),
                                           not_ready.reason));
    }
    send();
  }
  const avc::ack_t& ack = final_acks_.at(id);
  if (ack.status == avc::ack_t::STATUS_REFUSED) {
    throw CommandRefused(fmt::format("{} refused '{}': {}", ack.service, id, ack.reason));
  }
  if (ack.status != avc::ack_t::STATUS_DONE) {
    throw std::runtime_error(fmt::format("{} failed '{}': {}", ack.service, id, ack.reason));
  }
  return (MonotonicMicros() - sent_us) * 1e-6;
}

double CellClient::Robot(int8_t kind, std::chrono::milliseconds timeout) {
  avc::robot_command_t command{};
  command.request_id = NextId("robot");
  command.kind = kind;
  return SendUntilDone(
      command.request_id, [&] { PublishCommand(channels::kRobotCommand, command); }, timeout);
}

double CellClient::SetPlantKeepOut(const kinematics::PlantKeepOut& keep_out,
                                   std::chrono::milliseconds timeout) {
  avc::robot_command_t command{};
  command.request_id = NextId("keep-out");
  command.kind = avc::robot_command_t::KIND_SET_PLANT_KEEP_OUT;
  kinematics::RowMajorFromIsometry(keep_out.T_base_table, command.T_base_table);
  command.keep_out_z0 = keep_out.z0_m;
  command.keep_out_slab = keep_out.slab_m;
  command.keep_out_slabs = static_cast<int16_t>(keep_out.radius_m.size());
  command.keep_out_radius = keep_out.radius_m;
  return SendUntilDone(
      command.request_id, [&] { PublishCommand(channels::kRobotCommand, command); }, timeout);
}

double CellClient::MoveJoints(const kinematics::JointVector& q, std::chrono::milliseconds timeout) {
  avc::robot_command_t command{};
  command.request_id = NextId("move");
  command.kind = avc::robot_command_t::KIND_MOVE_JOINTS;
  for (int i = 0; i < 6; ++i) command.q[i] = q[i];
  return SendUntilDone(
      command.request_id, [&] { PublishCommand(channels::kRobotCommand, command); }, timeout);
}

double CellClient::TurntableGoto(double angle_rad, std::chrono::milliseconds timeout) {
  avc::turntable_command_t command{};
  command.request_id = NextId("table");
  command.kind = avc::turntable_command_t::KIND_GOTO;
  command.angle = angle_rad;
  return SendUntilDone(
      command.request_id, [&] { PublishCommand(channels::kTurntableCommand, command); }, timeout);
}

CapturedView CellClient::Capture(const std::string& image_id, int8_t encoding,
                                 std::chrono::milliseconds timeout) {
  avc::capture_request_t request{};
  request.image_id = image_id;
  request.encoding = encoding;
  CapturedView view;
  request.request_id = NextId("capture");
  const int64_t sent_wall = WallMicros();
  view.request_to_done_s = SendUntilDone(
      request.request_id, [&] { bus_.Publish(channels::kCaptureRequest, request); }, timeout);
  const auto arrived = [&] {
    return std::find_if(products_.begin(), products_.end(), [&](const auto& entry) {
      return entry.first.rfind("images/" + image_id + ".", 0) == 0;
    });
  };
  // DONE comes on the control link once any consumer (a recorder, say) has the whole image; our
  // own copy's last chunks on the bulk link can still be on their way.
  loop_.RunUntil([&] { return arrived() != products_.end(); }, kImageAfterDoneGrace);
  const auto found = arrived();
  if (found == products_.end()) {
    throw std::runtime_error(
        fmt::format("the camera said DONE but image {} did not arrive here "
                    "within {} ms of it",
                    image_id, kImageAfterDoneGrace.count()));
  }
  const auto& [product, received_wall] = found->second;
  if (view.image.decode(product.payload.data(), 0, static_cast<int>(product.payload.size())) < 0) {
    throw std::runtime_error("image " + image_id + " does not decode as image_t");
  }
  // Both ends stamp with this machine's wall clock.
  view.request_to_sent_s = (product.utime - sent_wall) * 1e-6;
  view.sent_to_received_s = (received_wall - product.utime) * 1e-6;
  products_.erase(found);
  return view;
}

}  // namespace avc::client
