// A heartbeat from its own thread keeps beating while the main thread is busy, follows the
// state it is given, and says STOPPING when it ends: what the robot watchdog relies on while a
// scan plans or reconstructs.

#include "core/bus/background_heartbeat.h"

#include <gtest/gtest.h>

#include <avc/heartbeat_t.hpp>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"

namespace avc::bus {
namespace {

using std::chrono::milliseconds;

TEST(BackgroundHeartbeat, BeatsWhileTheMainThreadBlocksAndStopsWithStopping) {
  Bus bus(InProcessBusOptions("cellh", "beat-test"));
  EventLoop loop;
  bus.AttachTo(loop);
  std::vector<avc::heartbeat_t> beats;
  bus.Subscribe<avc::heartbeat_t>(channels::kHeartbeat,
                                  [&](const avc::heartbeat_t& beat, const RxInfo&) {
                                    if (beat.service == "avc-orchestrator") beats.push_back(beat);
                                  });
  {
    BackgroundHeartbeat heartbeat(bus, "avc-orchestrator", milliseconds(50));
    heartbeat.Set(ServiceState::kBusy, "ACTIVE_VISION");
    // The main thread computes for 600 ms without running its loop...
    std::this_thread::sleep_for(milliseconds(600));
    // ...and the beats were sent all along: they are waiting to be handled.
    loop.RunUntil([] { return false; }, milliseconds(100));
    ASSERT_GE(beats.size(), 8u);
    EXPECT_EQ(beats.back().state, avc::heartbeat_t::STATE_BUSY);
    EXPECT_EQ(beats.back().detail, "ACTIVE_VISION");
    const int64_t span_us = beats.back().header.utime - beats.front().header.utime;
    EXPECT_LE(span_us / static_cast<int64_t>(beats.size() - 1), 120'000);  // about every 50 ms
  }
  // Beats sent before the end may still be queued: the last one heard must say STOPPING.
  const auto stopping = [&] {
    return !beats.empty() && beats.back().state == avc::heartbeat_t::STATE_STOPPING;
  };
  EXPECT_TRUE(loop.RunUntil(stopping, milliseconds(1000)));
  const size_t heard = beats.size();
  loop.RunUntil([] { return false; }, milliseconds(200));
  EXPECT_EQ(beats.size(), heard) << "beats went on after the end";
}

}  // namespace
}  // namespace avc::bus
