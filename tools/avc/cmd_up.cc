// avc up: starts the processes of a launch file on this host and supervises them.

#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/launch/find_program.h"
#include "core/launch/launch_file.h"
#include "core/launch/supervisor.h"
#include "core/util/host.h"
#include "core/util/log.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

constexpr char kUpExample[] = R"(Example launch file (TOML; YAML with the same keys works too):

  log_dir = "logs"                  # default: <launch file folder>/logs
  [env]                             # for every process
  AVC_CELL = "cell0"

  [[process]]
  name = "recorder"                 # unique; names <log_dir>/recorder.log
  command = "avc"                   # bare names: next to this avc first, then PATH
  args = ["record", "--output", "scan.lcmlog"]
  restart = "on-failure"            # always | on-failure | never
  stop_timeout = 5.0                # seconds from SIGTERM to SIGKILL

  [[process]]
  name = "collector"
  command = "avc"
  args = ["collect", "--output", "products"]
  host = "lab-pc-1"                 # only there; omit (or "*") for every host
  # also: env = { NAME = "value" }, working_dir = "." (relative to the launch file)

Stop with Ctrl-C or SIGTERM: every process gets SIGTERM, then SIGKILL after its stop_timeout.
Crashed processes restart after 0.2 s, doubling to 10 s while they keep crashing.
Exit code: 0 after a stop or when every process exited 0, 1 when one failed, 2 for a bad
launch file. Watch it with 'avc status'; see launch/demo-foundation.toml.)";

struct UpArgs {
  std::string launch_file;
  std::optional<std::string> host;
  std::optional<std::string> log_dir;
  bus::BusFlags bus;
};

// Command-line flags win, then the launch file's [env], then our environment. The children get
// the result, so supervisor and processes share one bus unless a process overrides it.
bus::BusOptions ResolveBus(const UpArgs& args, launch::LaunchSpec& spec) {
  bus::BusFlags flags = args.bus;
  auto from_file = [&](std::optional<std::string>& flag, const char* name) {
    if (auto it = spec.env.find(name); !flag && it != spec.env.end()) flag = it->second;
  };
  from_file(flags.lcm_url, "AVC_LCM_URL");
  from_file(flags.bulk_url, "AVC_BULK_URL");
  from_file(flags.cell, "AVC_CELL");
  bus::BusOptions options = bus::ResolveBusOptions(flags, "avc-up");
  spec.env["AVC_LCM_URL"] = options.control_url;
  spec.env["AVC_BULK_URL"] = options.bulk_url.empty() ? options.control_url : options.bulk_url;
  spec.env["AVC_CELL"] = options.cell;
  return options;
}

int RunUp(const UpArgs& args) {
  const std::string host = args.host.value_or(HostName());
  launch::LaunchSpec spec;
  try {
    spec = launch::LoadLaunchFile(args.launch_file);
    const size_t total = spec.processes.size();
    spec = launch::ForHost(std::move(spec), host);
    if (spec.processes.empty()) {
      std::cerr << "avc up: " << args.launch_file << ": none of its " << total
                << " processes runs on host '" << host
                << "' (their host keys name other machines; use --host NAME or host = \"*\")\n";
      return 2;
    }
    launch::ResolveCommands(spec, launch::SelfExecutableDir());
  } catch (const launch::LaunchFileError& e) {
    std::cerr << "avc up: " << e.what() << "\n";
    return 2;
  }
  if (args.log_dir) {
    spec.log_dir = std::filesystem::absolute(*args.log_dir).lexically_normal().string();
  }
  bus::BusOptions options;
  try {
    options = ResolveBus(args, spec);
  } catch (const std::invalid_argument& e) {
    std::cerr << "avc up: " << e.what() << "\n";
    return 2;
  }
  log::SetProcessName("avc-up");
  bus::Bus bus(options);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  launch::SupervisorOptions supervisor_options;
  supervisor_options.host = host;
  launch::Supervisor supervisor(std::move(spec), bus, loop, supervisor_options);
  return supervisor.Run();
}

}  // namespace

void RegisterUp(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<UpArgs>();
  CLI::App* command = root.add_subcommand(
      "up",
      "Start the processes of a launch file on this host and keep them running.\n"
      "Each process's output goes to <log_dir>/<name>.log; crashed processes are restarted;\n"
      "status is published on PROCESS_STATUS and heartbeat service \"avc-up\" ('avc status').");
  command->add_option("LAUNCHFILE", args->launch_file, "launch file (.toml, .yaml or .yml)")
      ->required();
  command->add_option("--host", args->host,
                      "run the processes meant for this host (default: this machine's name)");
  command->add_option("--log-dir", args->log_dir,
                      "folder for the process logs (default: log_dir of the launch file)");
  AddBusFlags(command, &args->bus);
  command->footer(kUpExample);
  SetGuardedRun(command, exit_code, [args] { return RunUp(*args); });
}

}  // namespace avc::cli
