#include "core/bus/heartbeat_monitor.h"

#include "core/bus/channels.h"
#include "core/bus/decode.h"

namespace avc::bus {

HeartbeatMonitor::HeartbeatMonitor(Bus& bus, bool all_cells) : bus_(bus) {
  // Cell ids are [a-z0-9_-]: literal in a regex.
  const std::string cell = all_cells ? "[a-z0-9_-]+" : bus.cell();
  subscription_ = bus_.SubscribeRegex(
      Link::kControl, cell + "/" + std::string(channels::kHeartbeat),
      [this](const uint8_t* data, size_t size, const RxInfo& info) {
        ServiceSighting sighting;
        if (!DecodeMessage(data, size, &sighting.beat)) {
          bus_.Reject(info, "does not decode as avc.heartbeat_t");
          return;
        }
        sighting.cell = info.channel.substr(0, info.channel.find('/'));
        sighting.heard_utime = info.recv_utime;
        const Key key{sighting.cell, sighting.beat.service, sighting.beat.host, sighting.beat.pid};
        sightings_[key] = std::move(sighting);
      });
}

HeartbeatMonitor::~HeartbeatMonitor() { bus_.Unsubscribe(subscription_); }

std::vector<ServiceSighting> HeartbeatMonitor::Sightings() const {
  std::vector<ServiceSighting> result;
  result.reserve(sightings_.size());
  for (const auto& [key, sighting] : sightings_) result.push_back(sighting);
  return result;
}

const ServiceSighting* HeartbeatMonitor::Find(const std::string& service, int8_t state) const {
  const ServiceSighting* newest = nullptr;
  for (const auto& [key, sighting] : sightings_) {
    if (sighting.beat.service != service || sighting.beat.state != state) continue;
    if (newest == nullptr || sighting.heard_utime > newest->heard_utime) newest = &sighting;
  }
  return newest;
}

void HeartbeatMonitor::ForgetSilentSince(int64_t utime) {
  std::erase_if(sightings_,
                [utime](const auto& entry) { return entry.second.heard_utime < utime; });
}

}  // namespace avc::bus
