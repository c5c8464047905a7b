#pragma once

// The simulated cell as the separate processes a lab runs: `avc sim cell` (all emulators) plus
// the three drivers (`avc robot`, `avc turntable`, `avc camera`) pointed at it over the real
// protocols, the planner and the three reconstruction stages (`avc planner`, `avc builder`,
// `avc clusterer`, `avc surfacer`),
// talking LCM on the given URLs, and optionally a recorder (`avc record`). Used by
// `avc bench devices`, `avc bench chaos` and the end-to-end tests. Ports are picked free at start;
// logs land in work_dir. The drivers obey only commands signed with the cell's key,
// work_dir/cell.key (made at the first start).

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/auth/command_key.h"
#include "core/bus/bus_options.h"
#include "core/launch/child_process.h"

namespace avc::bench {

struct CellProcessOptions {
  std::filesystem::path avc_binary;  // the `avc` executable
  std::filesystem::path work_dir;    // logs, pty link, truth.jsonl, HOME of the camera driver
  std::string lcm_url;
  std::string bulk_url;
  std::string cell = "cell0";
  double time_scale = 1;
  std::string plant = "rosette";
  int triangles = 20000;
  int width = 1280, height = 960;
  double table_speed_deg_s = 90;
  double capture_latency_s = 0;
  bool png = false;
  // More `avc sim cell` flags, e.g. {"--chessboard", "9x6", "--samples", "4"}.
  std::vector<std::string> extra_sim_args;
  // Also run `avc record` for the cell ("avc-record"), into work_dir/recordings/.
  bool record = false;
  // Run the services a scan plans and reconstructs with (avc-planner, -builder, -clusterer,
  // -surfacer).
  bool stages = true;
  // More flags for a service by name, e.g. {"avc-surfacer", {"--set", "surface.refine=false"}}.
  std::map<std::string, std::vector<std::string>> service_args;
  // Put before the command line of the cell's processes (simulator, drivers, recorder) and of
  // the services: {"ip", "netns", "exec", NAME} runs them in a network namespace (it execs the
  // command, so the pid and the signals are the process's own).
  std::vector<std::string> cell_prefix;
  std::vector<std::string> service_prefix;
};

class CellProcesses {
 public:
  // Starts the simulated cell and the drivers. Throws std::runtime_error when a process cannot
  // be started.
  explicit CellProcesses(const CellProcessOptions& options);
  // SIGTERM to every process, then SIGKILL after 5 s for any that ignores it.
  ~CellProcesses();
  CellProcesses(const CellProcesses&) = delete;
  CellProcesses& operator=(const CellProcesses&) = delete;

  // SIGKILLs the named process ("avc-robot", "avc-turntable", "avc-camera", "avc-sim",
  // "avc-builder", "avc-clusterer", "avc-surfacer", "avc-record"), as a crash would, and starts it
  // again the same way (its log goes on; a recorder starts a new recording). Throws
  // std::invalid_argument for an unknown name.
  void KillAndRestart(const std::string& name);

  // Names of processes that exited (with how), empty while all run.
  std::vector<std::string> Exited();
  // The last lines of every log, for error messages.
  std::string LogTails(int lines = 15) const;
  std::filesystem::path truth_log() const;
  // Where the recorder writes: one .lcmlog per start.
  std::filesystem::path recordings_dir() const { return work_dir_ / "recordings"; }
  // The key the drivers check motion commands with: give it to the CellClient.
  const auth::CommandKey& key() const { return key_; }

 private:
  struct Process {
    std::string name;
    std::filesystem::path log;
    // The command line of each start: the recorder's names a new file every time.
    std::function<std::vector<std::string>()> argv;
    launch::ChildProcess child;
  };
  void Start(const std::string& name, std::function<std::vector<std::string>()> argv);
  launch::ChildProcess Spawn(const std::filesystem::path& log, std::vector<std::string> argv) const;
  std::filesystem::path NextRecording() const;

  std::filesystem::path work_dir_;
  std::string lcm_url_, bulk_url_, cell_;
  auth::CommandKey key_;
  std::vector<Process> processes_;
};

// A bench cell with the `avc` next to this executable, on udpm multicast ports `port` (control)
// and `port + 1` (bulk, with a 4 MB receive buffer), staying on this machine (ttl 0).
CellProcessOptions LocalCellOptions(int port, const std::string& cell, double time_scale,
                                    const std::filesystem::path& work_dir);

// A cell on the bus a program already talks on (its URLs and cell id), with the `avc` at
// avc_binary and its logs in work_dir; the rest at the defaults.
CellProcessOptions CellOptionsOnBus(const bus::BusOptions& bus,
                                    const std::filesystem::path& avc_binary,
                                    const std::filesystem::path& work_dir);

// The bus options of a program that talks to that cell.
bus::BusOptions ClientBusOptions(const CellProcessOptions& options, const std::string& source);

// The last `lines` lines of a log file (empty if it cannot be read).
std::string LogTail(const std::filesystem::path& log, int lines);

// A TCP port on 127.0.0.1 nobody listens on right now (bound and closed), outside the ephemeral
// range; successive calls in one process walk the range, so cells started at once get their own.
int FreeTcpPort();

}  // namespace avc::bench
