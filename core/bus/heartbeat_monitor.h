#pragma once

// Who is alive on the bus: the latest heartbeat of every process (by cell, service, host and
// pid) with the time it was heard. Used by `avc status`; supervisors and the orchestrator use
// it to notice a service that went silent.

#include <avc/heartbeat_t.hpp>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/bus/bus.h"

namespace avc::bus {

struct ServiceSighting {
  std::string cell;
  avc::heartbeat_t beat;
  int64_t heard_utime = 0;  // receive time of the latest heartbeat
};

class HeartbeatMonitor {
 public:
  // Listens on the bus's own cell, or on every cell.
  HeartbeatMonitor(Bus& bus, bool all_cells);
  ~HeartbeatMonitor();
  HeartbeatMonitor(const HeartbeatMonitor&) = delete;
  HeartbeatMonitor& operator=(const HeartbeatMonitor&) = delete;

  // Latest sighting per process, ordered by cell, service, host, pid.
  std::vector<ServiceSighting> Sightings() const;
  // The newest sighting of service in state (any pid), or nullptr.
  const ServiceSighting* Find(const std::string& service, int8_t state) const;
  // Drops processes not heard since before utime (they stopped or died).
  void ForgetSilentSince(int64_t utime);

 private:
  using Key = std::tuple<std::string, std::string, std::string, int32_t>;

  Bus& bus_;
  Bus::SubscriptionId subscription_ = 0;
  std::map<Key, ServiceSighting> sightings_;
};

}  // namespace avc::bus
