#include "core/bus/heartbeat.h"

#include <unistd.h>

#include "core/bus/channels.h"
#include "core/util/host.h"
#include "core/util/log.h"
#include "core/util/version.h"

namespace avc::bus {

const char* ServiceStateName(int8_t state) {
  switch (state) {
    case avc::heartbeat_t::STATE_STARTING:
      return "STARTING";
    case avc::heartbeat_t::STATE_READY:
      return "READY";
    case avc::heartbeat_t::STATE_BUSY:
      return "BUSY";
    case avc::heartbeat_t::STATE_ERROR:
      return "ERROR";
    case avc::heartbeat_t::STATE_STOPPING:
      return "STOPPING";
    default:
      return "UNKNOWN";
  }
}

HeartbeatPublisher::HeartbeatPublisher(Bus& bus, EventLoop& loop, std::string service,
                                       EventLoop::Duration period)
    : bus_(bus),
      loop_(loop),
      service_(std::move(service)),
      host_(HostName()),
      started_us_(MonotonicMicros()) {
  timer_ = loop_.AddTimer(
      period, [this] { PublishNow(); }, /*repeating=*/true);
  PublishNow();
}

HeartbeatPublisher::~HeartbeatPublisher() { loop_.CancelTimer(timer_); }

void HeartbeatPublisher::Set(ServiceState state, std::string detail) {
  if (state == state_ && detail == detail_) return;
  if (state == ServiceState::kError && (state_ != state || detail != detail_)) {
    log::Error("{} is in ERROR: {}", service_, detail);
  }
  state_ = state;
  detail_ = std::move(detail);
  PublishNow();
}

void HeartbeatPublisher::PublishNow() {
  avc::heartbeat_t beat{};
  beat.service = service_;
  beat.host = host_;
  beat.pid = static_cast<int32_t>(getpid());
  beat.state = static_cast<int8_t>(state_);
  beat.detail = detail_;
  beat.version = std::string(Version());
  beat.uptime_us = MonotonicMicros() - started_us_;
  const BusStats stats = bus_.stats();
  beat.messages_received = stats.received;
  beat.messages_rejected = stats.rejected;
  try {
    bus_.Publish(channels::kHeartbeat, beat);
  } catch (const BusError& e) {
    log::Warn("heartbeat not sent: {}", e.what());
  }
}

}  // namespace avc::bus
