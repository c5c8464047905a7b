#include "bench/auth/auth_bench.h"

#include <fmt/format.h>

#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/turntable_command_t.hpp>
#include <avc/turntable_state_t.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>

#include "bench/registry.h"
#include "bench/summary.h"
#include "core/auth/command_auth.h"
#include "core/auth/command_key.h"
#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "core/launch/find_program.h"
#include "core/util/clock.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;
using Command = avc::turntable_command_t;

struct AuthBenchArgs {
  int iterations = 20000;  // in-process sign/verify timings
  int attacks = 50;        // commands of each bad kind at the live driver
  int genuine = 10;        // signed gotos between the attacks
  int port = 7691;
  std::string work_dir = "/tmp/avc-bench-auth";
  bool json = false;
};

Command Goto(const std::string& id, double angle) {
  Command command{};
  command.request_id = id;
  command.kind = Command::KIND_GOTO;
  command.angle = angle;
  return command;
}

// Microseconds per call of `fn`, in batches of 100.
Summary TimePerCall(int iterations, const std::function<void()>& fn) {
  std::vector<double> per_call_us;
  for (int batch = 0; batch < iterations / 100; ++batch) {
    const int64_t start = MonotonicMicros();
    for (int i = 0; i < 100; ++i) fn();
    per_call_us.push_back((MonotonicMicros() - start) / 100.0);
  }
  return Summarize(per_call_us);
}

nlohmann::json CostOfChecks(const AuthBenchArgs& args) {
  auth::CommandKey key = auth::GenerateCommandKey(fs::path(args.work_dir) / "timing.key");
  auth::CommandSigner signer(key, "bench", "cell0");
  auth::VerifierOptions options;
  options.key = key;
  auth::CommandVerifier verifier(options, "cell0/TURNTABLE_COMMAND", "cell0");
  Command command = Goto("t", 1.0);
  const Summary encode = TimePerCall(args.iterations, [&] { auth::CanonicalBytes(command); });
  const Summary sign =
      TimePerCall(args.iterations, [&] { signer.Sign(command, "cell0/TURNTABLE_COMMAND"); });
  const Summary verify = TimePerCall(args.iterations, [&] {
    signer.Sign(command, "cell0/TURNTABLE_COMMAND");
    if (!verifier.Check(command).empty()) throw std::logic_error("genuine command refused");
  });
  return {{"encode_us", encode.median},
          {"sign_us", sign.median},
          {"sign_and_verify_us", verify.median}};
}

// The live driver and what it answers.
class LiveTurntable {
 public:
  LiveTurntable(const AuthBenchArgs& args, const auth::CommandKey& key)
      : bus_(Options(args)),
        log_(fs::path(args.work_dir) / "turntable.log"),
        process_(launch::ChildProcess::Spawn(
            {{(launch::SelfExecutableDir() / "avc").string(), "turntable", "--emulate",
              "--emulate-speed", "720", "--poll-ms", "20", "--key", key.file.string(), "--lcm-url",
              bus_.options().control_url, "--bulk-url", bus_.options().bulk_url, "--cell",
              bus_.cell()},
             {},
             "",
             log_.string()})) {
    bus_.AttachTo(loop_);
    bus_.Subscribe<avc::ack_t>(channels::kAck, [this](const avc::ack_t& ack, const bus::RxInfo&) {
      if (ack.service == "avc-turntable") acks_.push_back(ack);
    });
    bus_.Subscribe<avc::turntable_state_t>(
        channels::kTurntableState,
        [this](const avc::turntable_state_t& state, const bus::RxInfo&) { angle_ = state.angle; });
    bool ready = false;
    bus_.Subscribe<avc::heartbeat_t>(
        channels::kHeartbeat, [&ready](const avc::heartbeat_t& beat, const bus::RxInfo&) {
          ready |= beat.service == "avc-turntable" && beat.state == avc::heartbeat_t::STATE_READY;
        });
    if (!loop_.RunUntil([&] { return ready || !process_.running(); }, milliseconds(15000)) ||
        !ready) {
      throw std::runtime_error("avc turntable did not become READY; see " + log_.string());
    }
  }
  ~LiveTurntable() {
    process_.Signal(SIGTERM);
    process_.WaitFor(milliseconds(5000));
  }

  bus::Bus& bus() { return bus_; }
  std::string Channel() const { return bus_.FullChannel(channels::kTurntableCommand); }
  std::optional<double> angle() const { return angle_; }

  // The final answer to `id` (waits up to `timeout`), or nullopt.
  std::optional<avc::ack_t> Answer(const std::string& id, size_t after, milliseconds timeout) {
    std::optional<avc::ack_t> found;
    loop_.RunUntil(
        [&] {
          for (size_t i = after; i < acks_.size(); ++i) {
            if (acks_[i].request_id == id && acks_[i].status != avc::ack_t::STATUS_ACCEPTED) {
              found = acks_[i];
              return true;
            }
          }
          return false;
        },
        timeout);
    return found;
  }
  size_t heard() const { return acks_.size(); }
  // ACCEPTED answers to `id` since `after`: a command that started a move.
  int Accepted(const std::string& id, size_t after) const {
    int accepted = 0;
    for (size_t i = after; i < acks_.size(); ++i) {
      accepted += acks_[i].request_id == id && acks_[i].status == avc::ack_t::STATUS_ACCEPTED;
    }
    return accepted;
  }
  void Settle() {
    loop_.RunUntil([] { return false; }, milliseconds(100));
  }

 private:
  static bus::BusOptions Options(const AuthBenchArgs& args) {
    bus::BusOptions options;
    options.control_url = fmt::format("udpm://239.255.76.67:{}?ttl=0", args.port);
    options.bulk_url = fmt::format("udpm://239.255.76.67:{}?ttl=0", args.port + 1);
    options.cell = "benchauth";
    options.source = "avc-bench-auth";
    return options;
  }

  bus::Bus bus_;
  bus::EventLoop loop_;
  fs::path log_;
  launch::ChildProcess process_;
  std::vector<avc::ack_t> acks_;
  std::optional<double> angle_;
};

struct KindResult {
  int sent = 0;
  int refused = 0;   // refused with an authentication reason
  int accepted = 0;  // started a move: must stay 0
  std::string example;
};

int Run(const AuthBenchArgs& args) {
  fs::create_directories(args.work_dir);
  for (const char* name : {"timing.key", "cell.key"}) fs::remove(fs::path(args.work_dir) / name);
  const nlohmann::json cost = CostOfChecks(args);

  const auth::CommandKey key = auth::GenerateCommandKey(fs::path(args.work_dir) / "cell.key");
  LiveTurntable table(args, key);
  bus::Bus& bus = table.bus();
  auth::CommandSigner signer(key, bus.options().source, bus.cell());
  auth::CommandKey other_key = key;
  other_key.bytes[5] ^= 0x40;
  auth::CommandSigner stranger(other_key, bus.options().source, bus.cell());
  auth::CommandSigner other_cell(key, "avc-scan@cell9", "cell9");
  ManualClock hour_ago(SystemClock().NowMicros() - 3'600'000'000);
  auth::CommandSigner late(key, "old-laptop", bus.cell(), &hour_ago);

  std::map<std::string, KindResult> results;
  std::optional<Command> last_genuine;
  int genuine_done = 0;
  double max_drift_rad = 0;
  const auto attack = [&](const std::string& kind, int n) {
    Command command = Goto(fmt::format("{}-{}", kind, n), 0.5 + 0.01 * n);
    bool stamped = true;  // "unsigned" goes as it is
    if (kind == "forged") {
      stranger.Sign(command, table.Channel());
    } else if (kind == "altered") {
      signer.Sign(command, table.Channel());
      command.angle += 1.0;
    } else if (kind == "other-device") {
      signer.Sign(command, bus.FullChannel(channels::kRobotCommand));
    } else if (kind == "other-cell") {
      other_cell.Sign(command, table.Channel());
      stamped = false;
    } else if (kind == "stale") {
      late.Sign(command, table.Channel());
      stamped = false;
    } else if (kind == "replayed") {
      command = *last_genuine;
      stamped = false;
    }
    const size_t before = table.heard();
    if (stamped) {
      bus.Publish(channels::kTurntableCommand, command);
    } else {
      bus.PublishUnstamped(channels::kTurntableCommand, command);
    }
    KindResult& result = results[kind];
    ++result.sent;
    const auto answer = table.Answer(command.request_id, before, milliseconds(1000));
    if (answer && answer->status == avc::ack_t::STATUS_REFUSED &&
        answer->reason.rfind("authentication: ", 0) == 0) {
      ++result.refused;
      if (result.example.empty()) result.example = answer->reason;
    }
    result.accepted += table.Accepted(command.request_id, before);
  };
  const std::vector<std::string> kinds = {"unsigned",   "forged", "altered", "other-device",
                                          "other-cell", "stale",  "replayed"};
  for (int g = 0; g < args.genuine; ++g) {
    Command command = Goto(fmt::format("genuine-{}", g), 0.2 * (g + 1));
    std::optional<avc::ack_t> answer;
    for (int attempt = 0; attempt < 5 && !answer; ++attempt) {
      const size_t before = table.heard();
      signer.Sign(command, table.Channel());
      bus.Publish(channels::kTurntableCommand, command);
      answer = table.Answer(command.request_id, before, milliseconds(5000));
    }
    if (!answer || answer->status != avc::ack_t::STATUS_DONE) {
      throw std::runtime_error(fmt::format("genuine goto {} was not done: {}", g,
                                           answer ? answer->reason : "no answer"));
    }
    ++genuine_done;
    last_genuine = command;
    table.Settle();
    const double rest = table.angle().value_or(0);
    for (int n = g * args.attacks / args.genuine; n < (g + 1) * args.attacks / args.genuine; ++n) {
      for (const std::string& kind : kinds) attack(kind, n);
    }
    table.Settle();
    max_drift_rad = std::max(max_drift_rad, std::abs(table.angle().value_or(0) - rest));
  }

  nlohmann::ordered_json report;
  report["cost"] = cost;
  report["genuine"] = {{"sent", args.genuine}, {"done", genuine_done}};
  std::cout << fmt::format(
      "signing and checking a turntable_command_t (median of {} calls in batches of 100):\n"
      "  encode alone {:.2f} us, sign {:.2f} us, sign + verify {:.2f} us\n\n"
      "avc turntable --emulate with a key: {} genuine gotos done of {}; between them:\n",
      args.iterations, cost["encode_us"].get<double>(), cost["sign_us"].get<double>(),
      cost["sign_and_verify_us"].get<double>(), genuine_done, args.genuine);
  std::cout << fmt::format("  {:<13} {:>5} {:>8} {:>9}  {}\n", "kind", "sent", "refused",
                           "accepted", "reason (first)");
  int total_accepted = 0;
  for (const std::string& kind : kinds) {
    const KindResult& r = results[kind];
    total_accepted += r.accepted;
    std::cout << fmt::format("  {:<13} {:>5} {:>8} {:>9}  {}\n", kind, r.sent, r.refused,
                             r.accepted, r.example.substr(0, 90));
    report["attacks"][kind] = {{"sent", r.sent}, {"refused", r.refused}, {"accepted", r.accepted}};
  }
  std::cout << fmt::format("  table moved during the attacks: {:.4f} deg at most\n",
                           max_drift_rad * 180 / std::numbers::pi);
  report["max_drift_deg"] = max_drift_rad * 180 / std::numbers::pi;
  if (args.json) std::cout << report.dump() << "\n";
  return total_accepted == 0 && genuine_done == args.genuine ? 0 : 1;
}

}  // namespace

int RunAuthBenchmark(const std::vector<std::string>& arguments) {
  AuthBenchArgs args;
  CLI::App app{
      "avc bench auth: the cost of signing and checking a motion command, and a live avc\n"
      "turntable process under bad commands (unsigned, forged, altered, signed for another\n"
      "device, from another cell, stale, replayed) between genuine signed gotos.",
      "avc bench auth"};
  app.add_option("--iterations", args.iterations, "sign/verify calls timed")
      ->capture_default_str()
      ->check(CLI::Range(100, 10'000'000));
  app.add_option("--attacks", args.attacks, "commands of each bad kind")
      ->capture_default_str()
      ->check(CLI::Range(1, 100'000));
  app.add_option("--genuine", args.genuine, "genuine gotos (the attacks are spread between)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--port", args.port, "udpm port of the control link (the bulk one is +1)")
      ->capture_default_str();
  app.add_option("--work-dir", args.work_dir, "keys and the driver's log")->capture_default_str();
  app.add_flag("--json", args.json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  return Run(args);
}

}  // namespace avc::bench
