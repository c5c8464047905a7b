#pragma once

// Records bus traffic into an LCM log : a run_info_t first,
// then every message of the cell (or of every cell) from the control and bulk links, stamped
// with its receive time, flushed to disk periodically and on Stop() so a crash or a signal
// loses at most one flush interval (lcm-logger loses its buffer on exit, D6).
//
// The recorder is also a product receiver named "recorder". Its raw subscription comes first,
// so LCM hands each chunk to it before the receiver sees it: a product is acknowledged by
// "recorder" only once its chunks are in the log.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/products/product_receiver.h"

namespace avc::record {

class RecordError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RecorderOptions {
  std::filesystem::path output;  // must not exist yet
  bool all_cells = false;        // false: "<cell>/.*" only
  std::chrono::milliseconds flush_interval{200};
  std::string command_line;   // for run_info_t
  std::string config_format;  // e.g. "yaml"; empty when there is no config
  std::string config_text;
};

struct RecorderStats {
  int64_t events = 0;  // events written, run_info_t included
  int64_t bytes = 0;   // payload bytes of those events
  int64_t write_errors = 0;
  int64_t flushes = 0;
};

class Recorder {
 public:
  // Creates the log and writes run_info_t. Throws RecordError naming the file when it exists
  // or cannot be created. bus and loop must outlive the recorder.
  Recorder(bus::Bus& bus, bus::EventLoop& loop, RecorderOptions options);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  // Writes what is buffered to disk (fflush + fsync).
  void Flush();
  // Stops recording: unsubscribes, flushes and closes the log. Idempotent.
  void Stop();

  const RecorderStats& stats() const { return stats_; }
  const std::filesystem::path& output() const { return options_.output; }
  bool stopped() const { return file_ == nullptr; }

 private:
  void WriteRunInfo();
  void Write(const std::string& channel, int64_t utime, const uint8_t* data, size_t size);

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  RecorderOptions options_;
  std::unique_ptr<lcm::LogFile> file_;
  std::vector<bus::Bus::SubscriptionId> subscriptions_;
  std::unique_ptr<products::ProductReceiver> product_receiver_;
  // Products with a chunk that could not be written: refused once complete, so not acknowledged.
  std::set<std::string> unlogged_products_;
  bus::EventLoop::TimerId flush_timer_ = 0;
  bool dirty_ = false;
  RecorderStats stats_;
};

}  // namespace avc::record
