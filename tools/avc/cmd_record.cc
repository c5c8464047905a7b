// avc record: the cell's recorder service.

#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/bus/service_runtime.h"
#include "core/record/recorder.h"
#include "core/util/clock.h"
#include "core/util/log.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct RecordArgs {
  std::string output;
  bool all_cells = false;
  std::string config;
  int flush_ms = 200;
  bus::BusFlags bus;
};

// The exact command line, for the log header (CLI11 does not keep argv).
std::string CommandLine() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string line;
  std::string arg;
  while (std::getline(in, arg, '\0')) {
    if (!line.empty()) line += ' ';
    line += arg.find(' ') == std::string::npos ? arg : "'" + arg + "'";
  }
  return line;
}

std::string ConfigFormat(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".yaml" || extension == ".yml") return "yaml";
  if (extension == ".toml") return "toml";
  if (extension == ".json") return "json";
  return "text";
}

std::string ReadConfig(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw std::runtime_error("config file " + path + " does not exist or is not a file");
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw std::runtime_error("cannot read config file " + path);
  return text.str();
}

std::string Detail(const record::RecorderStats& stats) {
  std::string detail =
      fmt::format("{} events, {:.1f} MB", stats.events, static_cast<double>(stats.bytes) / 1e6);
  if (stats.write_errors > 0) detail += fmt::format(", {} write errors", stats.write_errors);
  return detail;
}

// LCM's receive thread may still hold messages that arrived before the signal: take them until
// the bus has been quiet for a moment, within a bound, so a stop loses nothing already sent.
void DrainBus(bus::Bus& bus) {
  constexpr int64_t kQuietUs = 100'000;
  constexpr int64_t kMaxUs = 2'000'000;
  const int64_t start = MonotonicMicros();
  int64_t last_message = start;
  while (MonotonicMicros() - start < kMaxUs) {
    if (bus.DispatchPending() > 0) {
      last_message = MonotonicMicros();
    } else if (MonotonicMicros() - last_message >= kQuietUs) {
      return;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
}

// "%Y%m%d-%H%M%S" and other strftime fields in --output, in local time, so a restarted or
// repeated recorder starts a new log instead of refusing an existing one.
std::string ExpandTimeFields(const std::string& pattern) {
  if (pattern.find('%') == std::string::npos) return pattern;
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  std::string expanded(pattern.size() + 256, '\0');
  const size_t size = std::strftime(expanded.data(), expanded.size(), pattern.c_str(), &local);
  if (size == 0) throw std::runtime_error("cannot expand the time fields of --output " + pattern);
  expanded.resize(size);
  return expanded;
}

int RunRecord(RecordArgs args) {
  args.output = ExpandTimeFields(args.output);
  record::RecorderOptions options;
  options.output = args.output;
  options.all_cells = args.all_cells;
  options.flush_interval = std::chrono::milliseconds(args.flush_ms);
  options.command_line = CommandLine();
  if (!args.config.empty()) {
    options.config_text = ReadConfig(args.config);
    options.config_format = ConfigFormat(args.config);
  }
  // Signals are handled from here on, so a stop request right after READY is never fatal.
  bus::ServiceRuntime runtime("avc-record", args.bus);
  record::Recorder recorder(runtime.bus(), runtime.loop(), options);
  auto refresh = [&] {
    const record::RecorderStats& stats = recorder.stats();
    runtime.heartbeat().Set(
        stats.write_errors > 0 ? bus::ServiceState::kError : bus::ServiceState::kReady,
        Detail(stats));
  };
  refresh();
  const bus::EventLoop::TimerId refresh_timer =
      runtime.loop().AddTimer(std::chrono::seconds(1), refresh, /*repeating=*/true);
  log::Info("recording {} into {}", args.all_cells ? "every cell" : "cell " + runtime.bus().cell(),
            args.output);

  runtime.Run();
  runtime.loop().CancelTimer(refresh_timer);
  runtime.heartbeat().Set(bus::ServiceState::kStopping, Detail(recorder.stats()));
  DrainBus(runtime.bus());
  recorder.Stop();

  const record::RecorderStats& stats = recorder.stats();
  std::cout << fmt::format("avc record: wrote {} events ({:.1f} MB) to {}{}\n", stats.events,
                           static_cast<double>(stats.bytes) / 1e6, args.output,
                           stats.write_errors > 0
                               ? fmt::format("; {} events LOST to write errors", stats.write_errors)
                               : "");
  return stats.write_errors > 0 ? 1 : 0;
}

}  // namespace

void RegisterRecord(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<RecordArgs>();
  CLI::App* command = root.add_subcommand(
      "record",
      "Record the cell's bus traffic into an LCM log until Ctrl-C or SIGTERM.\n"
      "The log starts with a RUN_INFO event (version, command line, URLs, host, --config text),\n"
      "then holds every message on \"<cell>/...\" from the control and bulk URLs, stamped with\n"
      "its receive time. Flushes to disk every --flush-ms and on stop. Acknowledges products as\n"
      "receiver \"recorder\" once their chunks are in the log, so producers can require it.\n"
      "Heartbeat service \"avc-record\": READY with \"<events> events, <MB> MB\".\n"
      "Replay a log with 'avc replay'.");
  command
      ->add_option("-o,--output", args->output,
                   "log file to create (never overwritten); strftime fields such as %Y%m%d-%H%M%S "
                   "are filled in with the local time")
      ->required();
  command->add_flag("--all-cells", args->all_cells,
                    "record every cell on the network, not only --cell");
  command->add_option("--config", args->config,
                      "configuration file whose text is stored in the RUN_INFO header");
  command->add_option("--flush-ms", args->flush_ms, "milliseconds between flushes to disk")
      ->capture_default_str()
      ->check(CLI::Range(1, 60'000));
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunRecord(*args); });
}

}  // namespace avc::cli
