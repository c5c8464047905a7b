#pragma once

// Deterministic single-process replay: reads a
// log in order on one thread and feeds each event to the selected nodes over an in-process bus
// whose clock is the event's log time. No sockets, no wall clock, so replaying the same log
// twice gives the same outputs byte for byte.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/record/node_registry.h"

namespace avc::record {

class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ReplayOptions {
  std::filesystem::path log;
  std::filesystem::path output_dir;  // created; refused if it exists and is not empty
  std::vector<std::string> nodes;    // empty: every registered node
  std::string cell;                  // empty: the cell of the log's first RUN_INFO event
};

struct NodeOutput {
  std::string name;
  std::string description;                   // the node's own one-line account
  std::filesystem::path dir;                 // empty if the node writes no files
  std::vector<std::filesystem::path> files;  // relative to the replay output dir, sorted
};

struct ReplaySummary {
  std::string cell;
  int64_t events = 0;  // events replayed
  int64_t bytes = 0;   // their payload bytes
  int64_t first_utime = 0;
  int64_t last_utime = 0;
  // Damage in the log, events that could not be published, handlers that threw.
  std::vector<std::string> warnings;
  std::vector<NodeOutput> nodes;
};

class ReplayRunner {
 public:
  ReplayRunner(const NodeRegistry& registry, ReplayOptions options);

  // Replays the whole log. Throws ReplayError naming the file for an unreadable log, one that
  // is not an LCM log, an unknown node or a non-empty output directory. Damage inside a log
  // that has intact events is not an error: it is listed in the summary's warnings.
  ReplaySummary Run();

 private:
  std::string ResolveCell() const;
  void PrepareOutputDir() const;

  const NodeRegistry& registry_;
  ReplayOptions options_;
};

// The cell of the first RUN_INFO event in the log. Throws ReplayError if the file is not an
// LCM log or holds no RUN_INFO.
std::string CellOfLog(const std::filesystem::path& log);

}  // namespace avc::record
