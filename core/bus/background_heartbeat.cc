#include "core/bus/background_heartbeat.h"

#include <utility>

namespace avc::bus {

BackgroundHeartbeat::BackgroundHeartbeat(Bus& bus, std::string service, EventLoop::Duration period)
    // The publisher's timer is set up before the thread starts, so it is the only thread to
    // touch the loop from then on.
    : publisher_(bus, loop_, std::move(service), period), thread_([this] { loop_.Run(); }) {}

BackgroundHeartbeat::~BackgroundHeartbeat() {
  loop_.Quit();
  thread_.join();
  publisher_.Set(ServiceState::kStopping, "exiting");  // the loop has stopped: ours to touch
}

void BackgroundHeartbeat::Set(ServiceState state, std::string detail) {
  loop_.Post([this, state, detail = std::move(detail)]() mutable {
    publisher_.Set(state, std::move(detail));
  });
}

}  // namespace avc::bus
