// avc replay: deterministic single-process replay of a recorded log through processing nodes.

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "core/record/builtin_nodes.h"
#include "core/record/replay.h"
#include "core/util/log.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/scan_replay_node.h"

namespace avc::cli {
namespace {

struct ReplayArgs {
  std::string log;
  std::string output;
  std::vector<std::string> nodes;
  bool list_nodes = false;
  std::string cell;
};

void PrintNodes(const record::NodeRegistry& registry) {
  for (const record::NodeRegistry::Entry* entry : registry.List()) {
    std::cout << fmt::format("{:<12} {}\n", entry->name, entry->description);
  }
}

void PrintSummary(const record::ReplaySummary& summary, const std::string& log) {
  std::cout << fmt::format(
      "replayed {} events ({:.1f} MB, {:.1f} s of log time) of cell {} from {}\n", summary.events,
      static_cast<double>(summary.bytes) / 1e6,
      static_cast<double>(summary.last_utime - summary.first_utime) / 1e6, summary.cell, log);
  for (const record::NodeOutput& node : summary.nodes) {
    std::cout << fmt::format("node {}: {}\n", node.name, node.description);
    for (const std::filesystem::path& file : node.files) std::cout << "  " << file.string() << "\n";
  }
  for (const std::string& warning : summary.warnings) {
    std::cerr << "avc replay: warning: " << warning << "\n";
  }
}

int RunReplay(const ReplayArgs& args) {
  log::SetProcessName("avc-replay");
  record::NodeRegistry registry;
  record::RegisterBuiltinNodes(registry);
  RegisterScanReplayNode(registry);
  if (args.list_nodes) {
    PrintNodes(registry);
    return 0;
  }
  if (args.log.empty() || args.output.empty()) {
    std::cerr << "avc replay: give the LOG to replay and --output DIR (see 'avc replay --help')\n";
    return 2;
  }
  record::ReplayOptions options;
  options.log = args.log;
  options.output_dir = args.output;
  options.nodes = args.nodes;
  options.cell = args.cell;
  const record::ReplaySummary summary = record::ReplayRunner(registry, options).Run();
  PrintSummary(summary, args.log);
  return 0;
}

}  // namespace

void RegisterReplay(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* command = root.add_subcommand(
      "replay",
      "Replay a recorded log through processing nodes, deterministically, in one process.\n"
      "Every event goes, in log order, to the nodes over an in-process bus whose clock is the\n"
      "log time: no network and no wall clock, so replaying a log twice gives identical files.\n"
      "Each node writes under --output (the archive node into archive/). A truncated log (a\n"
      "crash while recording) is replayed up to the damage, with a warning naming the event.\n"
      "Example: avc replay scan.lcmlog --output /tmp/scan-replay");
  command->add_option("LOG", args->log, "LCM log written by 'avc record'");
  command->add_option("-o,--output", args->output,
                      "directory for the nodes' outputs; created, and refused if not empty");
  command
      ->add_option("--nodes", args->nodes,
                   "comma-separated nodes to run (default: all; see --list-nodes)")
      ->delimiter(',');
  command->add_flag("--list-nodes", args->list_nodes, "list the replayable nodes and exit");
  command->add_option("--cell", args->cell,
                      "cell whose channels the nodes listen to (default: from the log's RUN_INFO)");
  SetGuardedRun(command, exit_code, [args] { return RunReplay(*args); });
}

}  // namespace avc::cli
