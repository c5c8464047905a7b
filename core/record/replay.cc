#include "core/record/replay.h"

#include <fmt/format.h>

#include <algorithm>
#include <avc/run_info_t.hpp>
#include <memory>
#include <set>

#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "core/bus/channels.h"
#include "core/bus/decode.h"
#include "core/record/log_reader.h"
#include "core/util/clock.h"

namespace avc::record {
namespace {

// LCM's own limit: replay feeds whatever was recorded, even from a bus with a larger cap.
constexpr size_t kLcmMaxMessageBytes = size_t{1} << 28;

bool IsRunInfoChannel(const std::string& channel) {
  const std::string suffix = "/" + std::string(channels::kRunInfo);
  return channel.size() > suffix.size() &&
         channel.compare(channel.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<std::filesystem::path> FilesUnder(const std::filesystem::path& dir,
                                              const std::filesystem::path& base) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  if (dir.empty() || !std::filesystem::is_directory(dir, error)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path().lexically_relative(base));
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Throws ReplayError naming the file unless it holds at least one intact LCM event.
void RequireLcmLog(const std::filesystem::path& log) {
  try {
    LogReader reader(log);
    if (reader.Next() == nullptr) {
      throw ReplayError(fmt::format("{} is not an LCM log: no event found in its {} bytes",
                                    log.string(), reader.file_size()));
    }
  } catch (const LogError& e) {
    throw ReplayError(e.what());
  }
}

}  // namespace

std::string CellOfLog(const std::filesystem::path& log) {
  try {
    LogReader reader(log);
    while (const lcm::LogEvent* event = reader.Next()) {
      if (!IsRunInfoChannel(event->channel)) continue;
      const std::string prefix = event->channel.substr(0, event->channel.find('/'));
      avc::run_info_t info;
      if (event->datalen >= 0 &&
          bus::DecodeMessage(event->data, static_cast<size_t>(event->datalen), &info) &&
          bus::IsValidCellId(info.header.cell)) {
        return info.header.cell;
      }
      if (bus::IsValidCellId(prefix)) return prefix;
    }
    if (reader.events() == 0) {
      throw ReplayError(fmt::format("{} is not an LCM log: no event found in its {} bytes",
                                    log.string(), reader.file_size()));
    }
    throw ReplayError(fmt::format("{} has no RUN_INFO event ({} events); give the cell with --cell",
                                  log.string(), reader.events()));
  } catch (const LogError& e) {
    throw ReplayError(e.what());
  }
}

ReplayRunner::ReplayRunner(const NodeRegistry& registry, ReplayOptions options)
    : registry_(registry), options_(std::move(options)) {}

std::string ReplayRunner::ResolveCell() const {
  if (options_.cell.empty()) return CellOfLog(options_.log);
  if (!bus::IsValidCellId(options_.cell)) {
    throw ReplayError("cell id '" + options_.cell +
                      "' is invalid: use 1-16 characters of a-z, 0-9, '_' or '-'");
  }
  // CellOfLog is not needed, but a file that is not a log must still be refused before the
  // output directory is made (it would otherwise "replay" 0 events without an error).
  RequireLcmLog(options_.log);
  return options_.cell;
}

void ReplayRunner::PrepareOutputDir() const {
  const std::filesystem::path& dir = options_.output_dir;
  if (dir.empty()) throw ReplayError("no output directory given");
  std::error_code error;
  if (std::filesystem::exists(dir, error)) {
    if (!std::filesystem::is_directory(dir, error)) {
      throw ReplayError(dir.string() + " exists and is not a directory");
    }
    if (!std::filesystem::is_empty(dir, error)) {
      throw ReplayError(dir.string() +
                        " is not empty; refusing to mix outputs of different replays (choose a new "
                        "output directory)");
    }
  }
  std::filesystem::create_directories(dir, error);
  if (error) throw ReplayError("cannot create " + dir.string() + ": " + error.message());
}

ReplaySummary ReplayRunner::Run() {
  std::vector<std::string> names = options_.nodes;
  if (names.empty()) {
    for (const NodeRegistry::Entry* entry : registry_.List()) names.push_back(entry->name);
  }
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (!registry_.Contains(name)) {
      try {
        registry_.Get(name);
      } catch (const std::invalid_argument& e) {
        throw ReplayError(e.what());
      }
    }
    if (!seen.insert(name).second) throw ReplayError("replay node '" + name + "' given twice");
  }

  ReplaySummary summary;
  summary.cell = ResolveCell();
  std::unique_ptr<LogReader> reader;
  try {
    reader = std::make_unique<LogReader>(options_.log);
  } catch (const LogError& e) {
    throw ReplayError(e.what());
  }
  PrepareOutputDir();

  ManualClock clock;
  bus::BusOptions bus_options = bus::InProcessBusOptions(summary.cell, "replay");
  bus_options.max_message_bytes = kLcmMaxMessageBytes;
  bus::Bus bus(bus_options, &clock);

  std::vector<std::pair<std::string, std::unique_ptr<ReplayNode>>> nodes;
  for (const std::string& name : names) {
    nodes.emplace_back(name, registry_.Get(name).factory(bus, options_.output_dir));
  }

  while (const lcm::LogEvent* event = reader->Next()) {
    if (summary.events == 0) summary.first_utime = event->timestamp;
    summary.last_utime = event->timestamp;
    clock.Set(event->timestamp);
    try {
      bus.PublishRaw(bus::Link::kControl, event->channel, event->data,
                     static_cast<size_t>(event->datalen));
    } catch (const bus::BusError& e) {
      summary.warnings.push_back(fmt::format("{}: event {} on {} not replayed: {}",
                                             options_.log.string(), reader->events() - 1,
                                             event->channel, e.what()));
      continue;
    }
    bus.DispatchPending();
    ++summary.events;
    summary.bytes += event->datalen;
  }
  for (auto& entry : nodes) entry.second->Finish();
  bus.DispatchPending();  // what Finish published

  summary.warnings.insert(summary.warnings.end(), reader->warnings().begin(),
                          reader->warnings().end());
  const bus::BusStats stats = bus.stats();
  if (stats.handler_errors > 0) {
    summary.warnings.push_back(fmt::format(
        "{} message handlers failed during the replay (see the log above)", stats.handler_errors));
  }
  if (stats.rejected > 0) {
    summary.warnings.push_back(
        fmt::format("{} messages were rejected as malformed (see the log above)", stats.rejected));
  }
  for (const auto& [name, node] : nodes) {
    NodeOutput output;
    output.name = name;
    output.description = node->Describe();
    output.dir = node->OutputDir();
    output.files = FilesUnder(output.dir, options_.output_dir);
    summary.nodes.push_back(std::move(output));
  }
  return summary;
}

}  // namespace avc::record
