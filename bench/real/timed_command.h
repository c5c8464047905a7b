#pragma once

// Runs a command to its end and measures what it cost: wall time and the peak resident memory
// of that process alone (wait4's rusage, so earlier children do not count).

#include <filesystem>
#include <string>
#include <vector>

namespace avc::bench {

struct TimedRun {
  int exit_code = -1;  // -1 when killed by a signal
  std::string status;  // "exited with code 0", "killed by SIGKILL"
  double wall_s = 0;
  double peak_memory_mb = 0;
};

// stdout and stderr go to `log_file` (created). Throws std::runtime_error when the command cannot
// be started.
TimedRun RunTimed(const std::vector<std::string>& argv, const std::filesystem::path& log_file);

}  // namespace avc::bench
