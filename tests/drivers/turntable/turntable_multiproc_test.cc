// `avc turntable --emulate` as a real process on real udpm:// URLs (inside the test's private
// network namespace): it becomes READY, a goto published from here is acknowledged ACCEPTED and
// DONE, the state reports the commanded angle, and SIGTERM ends it cleanly.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/turntable_command_t.hpp>
#include <avc/turntable_state_t.hpp>
#include <csignal>
#include <filesystem>
#include <numbers>
#include <optional>

#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "tests/support/test_support.h"

namespace avc::turntable {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;
using std::chrono::seconds;

std::string ReadIfExists(const fs::path& path) {
  return fs::exists(path) ? testing::ReadFile(path) : std::string("(no output)");
}

TEST(TurntableMultiproc, EmulatedServiceMovesOnCommandAndStopsOnSigterm) {
  testing::TempDir dir("avc-turntable-mp");
  const fs::path output = dir / "turntable.out";

  bus::Bus bus(bus::ResolveBusOptions({}, "turntable-test"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  std::optional<avc::heartbeat_t> health;
  std::vector<avc::ack_t> acks;
  std::optional<avc::turntable_state_t> state;
  bus.Subscribe<avc::heartbeat_t>(channels::kHeartbeat,
                                  [&](const avc::heartbeat_t& beat, const bus::RxInfo&) {
                                    if (beat.service == "avc-turntable") health = beat;
                                  });
  bus.Subscribe<avc::ack_t>(channels::kAck, [&](const avc::ack_t& ack, const bus::RxInfo&) {
    if (ack.request_id == "mp-goto") acks.push_back(ack);
  });
  bus.Subscribe<avc::turntable_state_t>(
      channels::kTurntableState,
      [&](const avc::turntable_state_t& s, const bus::RxInfo&) { state = s; });

  launch::ChildProcess service =
      launch::ChildProcess::Spawn({{testing::Executable("avc").string(), "turntable", "--emulate",
                                    "--emulate-speed", "360", "--poll-ms", "50"},
                                   {},
                                   "",
                                   output.string()});
  ASSERT_TRUE(loop.RunUntil(
      [&] {
        return (health && health->state == avc::heartbeat_t::STATE_READY) || !service.running();
      },
      seconds(10)));
  ASSERT_TRUE(health && health->state == avc::heartbeat_t::STATE_READY)
      << "avc turntable never became READY:\n"
      << ReadIfExists(output);
  EXPECT_EQ(health->pid, service.pid());

  // 2 rad = 114.59 deg -> the table resolves 114.6. udpm may drop a datagram: resending the
  // same request id is harmless by contract, so resend until it is answered.
  avc::turntable_command_t command{};
  command.request_id = "mp-goto";
  command.kind = avc::turntable_command_t::KIND_GOTO;
  command.angle = 2.0;
  const auto done = [&] {
    for (const auto& ack : acks) {
      if (ack.status != avc::ack_t::STATUS_ACCEPTED) return true;
    }
    return false;
  };
  for (int attempt = 0; attempt < 10 && !done(); ++attempt) {
    bus.Publish(channels::kTurntableCommand, command);
    loop.RunUntil(done, seconds(1));
  }
  ASSERT_TRUE(done()) << ReadIfExists(output);
  ASSERT_FALSE(acks.empty());
  EXPECT_EQ(acks.front().status, avc::ack_t::STATUS_ACCEPTED);
  EXPECT_EQ(acks.back().status, avc::ack_t::STATUS_DONE) << acks.back().reason;
  EXPECT_EQ(acks.back().service, "avc-turntable");

  ASSERT_TRUE(
      loop.RunUntil([&] { return state && !state->moving && state->connected; }, seconds(3)));
  EXPECT_NEAR(state->angle, 2.0, 0.1 * std::numbers::pi / 180);

  ASSERT_TRUE(service.Signal(SIGTERM));
  const std::optional<int> status = service.WaitFor(milliseconds(5000));
  ASSERT_TRUE(status) << "avc turntable did not exit on SIGTERM";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
      << launch::DescribeWaitStatus(*status) << "\n"
      << ReadIfExists(output);
}

}  // namespace
}  // namespace avc::turntable
