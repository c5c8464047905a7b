// The watchdog's decisions with explicit times: who is watched, when a motion must stop, and why.

#include "drivers/robot/heartbeat_watchdog.h"

#include <gtest/gtest.h>

namespace avc::robot {
namespace {

using std::chrono::milliseconds;
using TimePoint = HeartbeatWatchdog::TimePoint;

const TimePoint kStart = TimePoint() + std::chrono::hours(1);

TEST(HeartbeatWatchdog, WatchesOnlyWhileTheServiceWasHeardRecently) {
  HeartbeatWatchdog watchdog("avc-orchestrator", milliseconds(500));
  EXPECT_FALSE(watchdog.ShouldWatch(kStart));  // never heard: manual use
  EXPECT_EQ(watchdog.StopReason(kStart), "");
  watchdog.Heard(kStart, true, "BUSY");
  EXPECT_TRUE(watchdog.ShouldWatch(kStart + milliseconds(5000)));
  EXPECT_FALSE(watchdog.ShouldWatch(kStart + milliseconds(5001)));
  HeartbeatWatchdog disabled("", milliseconds(500));
  disabled.Heard(kStart, true, "BUSY");
  EXPECT_FALSE(disabled.ShouldWatch(kStart));
}

TEST(HeartbeatWatchdog, StopsAfterTheTimeoutOrWhenTheServiceStops) {
  HeartbeatWatchdog watchdog("avc-orchestrator", milliseconds(500));
  watchdog.Heard(kStart, true, "BUSY");
  EXPECT_EQ(watchdog.StopReason(kStart + milliseconds(500)), "");
  EXPECT_EQ(watchdog.StopReason(kStart + milliseconds(612)),
            "avc-orchestrator heartbeat lost for 612 ms; arm stopped");
  watchdog.Heard(kStart + milliseconds(700), false, "ERROR");
  EXPECT_EQ(watchdog.Problem(kStart + milliseconds(710)), "avc-orchestrator reported ERROR");
  watchdog.Heard(kStart + milliseconds(800), true, "READY");
  EXPECT_EQ(watchdog.StopReason(kStart + milliseconds(810)), "");
}

}  // namespace
}  // namespace avc::robot
