#pragma once

// Publishes a process's configuration in force (TOML text, core/config/option_table.h) on
// CONFIG as config_t: at once and then every `period`, so a log recorded from any moment, and a
// scan that starts after the service, still hold it. The text does not change while the process
// runs (a new configuration is a restart), so the sequence stays 1.

#include <chrono>
#include <string>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"

namespace avc::bus {

class ConfigPublisher {
 public:
  // Loop thread only.
  ConfigPublisher(Bus& bus, EventLoop& loop, std::string service, std::string text,
                  EventLoop::Duration period = std::chrono::seconds(5));
  ~ConfigPublisher();
  ConfigPublisher(const ConfigPublisher&) = delete;
  ConfigPublisher& operator=(const ConfigPublisher&) = delete;

  const std::string& text() const { return text_; }
  const std::string& sha256() const { return sha256_; }

 private:
  void PublishNow();

  Bus& bus_;
  EventLoop& loop_;
  std::string service_;
  std::string text_;
  std::string sha256_;
  EventLoop::TimerId timer_ = 0;
};

}  // namespace avc::bus
