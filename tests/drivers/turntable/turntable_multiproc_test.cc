// `avc turntable --emulate` as a real process on real udpm:// URLs (inside the test's private
// network namespace): it becomes READY, an unsigned goto is refused and logged, a signed goto
// published from here is acknowledged ACCEPTED and DONE, the same signed datagram replayed is
// refused, the state reports the commanded angle, and SIGTERM ends it cleanly. Without a key it
// does not start unless unsigned commands are allowed, which it then warns about.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/turntable_command_t.hpp>
#include <avc/turntable_state_t.hpp>
#include <csignal>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/auth/command_auth.h"
#include "core/auth/command_key.h"
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

std::vector<std::string> TurntableArgs(std::vector<std::string> extra) {
  std::vector<std::string> argv = {testing::Executable("avc").string(),
                                   "turntable",
                                   "--emulate",
                                   "--emulate-speed",
                                   "360",
                                   "--poll-ms",
                                   "50"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

// The process's exit status once it ended by itself within 10 s.
std::optional<int> ExitOf(launch::ChildProcess& process) {
  return process.WaitFor(milliseconds(10000));
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
  bus.Subscribe<avc::ack_t>(
      channels::kAck, [&](const avc::ack_t& ack, const bus::RxInfo&) { acks.push_back(ack); });
  bus.Subscribe<avc::turntable_state_t>(
      channels::kTurntableState,
      [&](const avc::turntable_state_t& s, const bus::RxInfo&) { state = s; });

  const auth::CommandKey key = auth::GenerateCommandKey(dir / "cell.key");
  launch::ChildProcess service = launch::ChildProcess::Spawn(
      {TurntableArgs({"--key", key.file.string()}), {}, "", output.string()});
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
  const auto final_ack = [&](const std::string& id) -> std::optional<avc::ack_t> {
    for (const auto& ack : acks) {
      if (ack.request_id == id && ack.status != avc::ack_t::STATUS_ACCEPTED) return ack;
    }
    return std::nullopt;
  };
  const auto publish_until_answered = [&](const std::string& id,
                                          const std::function<void()>& send) {
    for (int attempt = 0; attempt < 10 && !final_ack(id); ++attempt) {
      send();
      loop.RunUntil([&] { return final_ack(id).has_value(); }, seconds(1));
    }
    return final_ack(id);
  };
  avc::turntable_command_t command{};
  command.kind = avc::turntable_command_t::KIND_GOTO;
  command.angle = 2.0;

  command.request_id = "mp-unsigned";
  const auto unsigned_answer = publish_until_answered(
      command.request_id, [&] { bus.Publish(channels::kTurntableCommand, command); });
  ASSERT_TRUE(unsigned_answer) << ReadIfExists(output);
  EXPECT_EQ(unsigned_answer->status, avc::ack_t::STATUS_REFUSED);
  EXPECT_NE(unsigned_answer->reason.find("unsigned command"), std::string::npos)
      << unsigned_answer->reason;

  auth::CommandSigner signer(key, bus.options().source, bus.cell());
  const std::string channel = bus.FullChannel(channels::kTurntableCommand);
  command.request_id = "mp-goto";
  const auto done = publish_until_answered(command.request_id, [&] {
    signer.Sign(command, channel);
    bus.Publish(channels::kTurntableCommand, command);
  });
  ASSERT_TRUE(done) << ReadIfExists(output);
  EXPECT_EQ(done->status, avc::ack_t::STATUS_DONE) << done->reason;
  EXPECT_EQ(done->service, "avc-turntable");

  // The last signed datagram again, under a new request id's clothes or not: a replay.
  acks.clear();
  command.request_id = "mp-goto";
  bus.PublishUnstamped(channels::kTurntableCommand, command);
  ASSERT_TRUE(loop.RunUntil([&] { return !acks.empty(); }, seconds(3))) << ReadIfExists(output);
  EXPECT_EQ(acks.front().status, avc::ack_t::STATUS_REFUSED);
  EXPECT_NE(acks.front().reason.find("replayed"), std::string::npos) << acks.front().reason;

  ASSERT_TRUE(
      loop.RunUntil([&] { return state && !state->moving && state->connected; }, seconds(3)));
  EXPECT_NEAR(state->angle, 2.0, 0.1 * std::numbers::pi / 180);

  ASSERT_TRUE(service.Signal(SIGTERM));
  const std::optional<int> status = service.WaitFor(milliseconds(5000));
  ASSERT_TRUE(status) << "avc turntable did not exit on SIGTERM";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
      << launch::DescribeWaitStatus(*status) << "\n"
      << ReadIfExists(output);
  // Every rejection is in the driver's log.
  const std::string log = ReadIfExists(output);
  EXPECT_NE(log.find("rejected goto 'mp-unsigned'"), std::string::npos) << log;
  EXPECT_NE(log.find("rejected goto 'mp-goto': replayed"), std::string::npos) << log;
}

TEST(TurntableMultiproc, WithoutAKeyItStartsOnlyWhenUnsignedCommandsAreAllowed) {
  testing::TempDir dir("avc-turntable-key");
  const std::map<std::string, std::string> env = {{"AVC_KEY_DIR", (dir / "keys").string()}};
  launch::ChildProcess refused =
      launch::ChildProcess::Spawn({TurntableArgs({}), env, "", (dir / "refused.out").string()});
  const std::optional<int> status = ExitOf(refused);
  ASSERT_TRUE(status) << "avc turntable without a key kept running";
  EXPECT_FALSE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0);
  const std::string why = ReadIfExists(dir / "refused.out");
  EXPECT_NE(why.find("no motion-command key"), std::string::npos) << why;
  EXPECT_NE(why.find("avc key generate"), std::string::npos) << why;

  // A key others may read is never used.
  fs::create_directories(dir / "keys");
  const std::string cell = bus::ResolveBusOptions({}, "x").cell;
  auth::GenerateCommandKey(dir / "keys" / (cell + ".key"));
  fs::permissions(dir / "keys" / (cell + ".key"), fs::perms::group_read, fs::perm_options::add);
  launch::ChildProcess exposed =
      launch::ChildProcess::Spawn({TurntableArgs({}), env, "", (dir / "exposed.out").string()});
  ASSERT_TRUE(ExitOf(exposed)) << "avc turntable used a group-readable key";
  EXPECT_NE(ReadIfExists(dir / "exposed.out").find("chmod 600"), std::string::npos)
      << ReadIfExists(dir / "exposed.out");

  const fs::path warned = dir / "unsigned.out";
  launch::ChildProcess allowed =
      launch::ChildProcess::Spawn({TurntableArgs({"--allow-unsigned"}),
                                   {{"AVC_KEY_DIR", (dir / "none").string()}},
                                   "",
                                   warned.string()});
  bus::Bus bus(bus::ResolveBusOptions({}, "turntable-test"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  bool ready = false;
  bus.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [&](const avc::heartbeat_t& beat, const bus::RxInfo&) {
        ready |= beat.service == "avc-turntable" && beat.state == avc::heartbeat_t::STATE_READY;
      });
  ASSERT_TRUE(loop.RunUntil([&] { return ready || !allowed.running(); }, seconds(10)));
  EXPECT_TRUE(ready) << ReadIfExists(warned);
  EXPECT_NE(ReadIfExists(warned).find("WARNING: unsigned motion commands are accepted"),
            std::string::npos)
      << ReadIfExists(warned);
  allowed.Signal(SIGTERM);
  EXPECT_TRUE(ExitOf(allowed));
}

}  // namespace
}  // namespace avc::turntable
