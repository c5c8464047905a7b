// avc status: which processes are alive on the bus, from their heartbeats and supervisors.

#include <fmt/format.h>

#include <avc/process_status_t.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/bus/heartbeat_monitor.h"
#include "core/util/clock.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct StatusArgs {
  double listen_s = 2.5;
  bool watch = false;
  bool all_cells = false;
  bool json = false;
  bus::BusFlags bus;
};

const char* ProcessStateName(int8_t state) {
  switch (state) {
    case avc::process_info_t::STATE_STARTING:
      return "STARTING";
    case avc::process_info_t::STATE_RUNNING:
      return "RUNNING";
    case avc::process_info_t::STATE_BACKOFF:
      return "BACKOFF";
    case avc::process_info_t::STATE_STOPPING:
      return "STOPPING";
    case avc::process_info_t::STATE_EXITED:
      return "EXITED";
    case avc::process_info_t::STATE_FAILED:
      return "FAILED";
    default:
      return "UNKNOWN";
  }
}

std::string Age(int64_t now_us, int64_t then_us) {
  return fmt::format("{:.1f}s", static_cast<double>(std::max<int64_t>(0, now_us - then_us)) / 1e6);
}

void PrintTables(const std::vector<bus::ServiceSighting>& sightings,
                 const std::map<std::string, avc::process_status_t>& supervisors, int64_t now_us) {
  std::cout << fmt::format("{:<8} {:<22} {:<16} {:>7} {:<9} {:>6}  {}\n", "CELL", "SERVICE", "HOST",
                           "PID", "STATE", "AGE", "DETAIL");
  for (const bus::ServiceSighting& s : sightings) {
    std::cout << fmt::format("{:<8} {:<22} {:<16} {:>7} {:<9} {:>6}  {}\n", s.cell, s.beat.service,
                             s.beat.host, s.beat.pid, bus::ServiceStateName(s.beat.state),
                             Age(now_us, s.heard_utime), s.beat.detail);
  }
  for (const auto& [host, status] : supervisors) {
    std::cout << fmt::format("\nsupervised by avc up on {} ({}):\n", host, status.launch_file);
    std::cout << fmt::format("  {:<20} {:>7} {:<9} {:>8}  {}\n", "PROCESS", "PID", "STATE",
                             "RESTARTS", "LAST EXIT");
    for (const avc::process_info_t& p : status.processes) {
      const std::string last_exit = p.last_signal != 0 ? fmt::format("signal {}", p.last_signal)
                                    : p.last_exit_code >= 0
                                        ? fmt::format("code {}", p.last_exit_code)
                                        : std::string("-");
      std::cout << fmt::format("  {:<20} {:>7} {:<9} {:>8}  {}\n", p.name, p.pid,
                               ProcessStateName(p.state), p.restarts, last_exit);
    }
  }
}

nlohmann::json ToJson(const std::vector<bus::ServiceSighting>& sightings, int64_t now_us) {
  nlohmann::json services = nlohmann::json::array();
  for (const bus::ServiceSighting& s : sightings) {
    services.push_back({{"cell", s.cell},
                        {"service", s.beat.service},
                        {"host", s.beat.host},
                        {"pid", s.beat.pid},
                        {"state", bus::ServiceStateName(s.beat.state)},
                        {"age_s", static_cast<double>(now_us - s.heard_utime) / 1e6},
                        {"detail", s.beat.detail},
                        {"version", s.beat.version},
                        {"messages_rejected", s.beat.messages_rejected}});
  }
  return {{"services", services}};
}

int RunStatus(const StatusArgs& args) {
  bus::Bus bus(bus::ResolveBusOptions(args.bus, "avc-status"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  loop.QuitOnTerminationSignals();
  bus::HeartbeatMonitor monitor(bus, args.all_cells);
  std::map<std::string, avc::process_status_t> supervisors;  // by host
  bus.Subscribe<avc::process_status_t>(
      channels::kProcessStatus, [&](const avc::process_status_t& status, const bus::RxInfo&) {
        supervisors[status.host] = status;
      });
  const auto listen = std::chrono::milliseconds(static_cast<int64_t>(args.listen_s * 1000));
  do {
    loop.RunUntil([&] { return loop.quitting(); }, listen);
    const int64_t now_us = bus.clock().NowMicros();
    // A process silent for three periods has stopped or died.
    monitor.ForgetSilentSince(now_us - 3'000'000);
    const std::vector<bus::ServiceSighting> sightings = monitor.Sightings();
    if (args.json) {
      std::cout << ToJson(sightings, now_us).dump() << std::endl;
    } else {
      if (args.watch) std::cout << "\x1b[H\x1b[2J";
      if (sightings.empty()) {
        std::cout << fmt::format(
            "no heartbeats on {} within {:.1f} s (bus {}). Are services running, on this cell, "
            "and is there a multicast route (see README, Networking)?\n",
            args.all_cells ? "any cell" : "cell " + bus.cell(), args.listen_s,
            bus.options().control_url);
      } else {
        PrintTables(sightings, supervisors, now_us);
      }
      std::cout.flush();
    }
    if (!args.watch) return sightings.empty() ? 1 : 0;
  } while (!loop.quitting());
  return 0;
}

}  // namespace

void RegisterStatus(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<StatusArgs>();
  CLI::App* command = root.add_subcommand(
      "status",
      "List the live processes of the cell from their heartbeats.\n"
      "Per process: service, host, pid, state, age of the last heartbeat, detail; and the\n"
      "processes each 'avc up' supervises.\n"
      "Exit code 1 when nobody was heard.");
  command->add_option("--listen", args->listen_s, "seconds to listen before printing")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 600.0));
  command->add_flag("-w,--watch", args->watch, "refresh every --listen seconds until Ctrl-C");
  command->add_flag("--all-cells", args->all_cells, "every cell on the network, not only --cell");
  command->add_flag("--json", args->json, "one JSON document per refresh instead of a table");
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunStatus(*args); });
}

}  // namespace avc::cli
