#include "core/bus/config_publisher.h"

#include <avc/config_t.hpp>

#include "core/bus/channels.h"
#include "core/util/log.h"
#include "core/util/sha256.h"

namespace avc::bus {

ConfigPublisher::ConfigPublisher(Bus& bus, EventLoop& loop, std::string service, std::string text,
                                 EventLoop::Duration period)
    : bus_(bus),
      loop_(loop),
      service_(std::move(service)),
      text_(std::move(text)),
      sha256_(Sha256Hex(text_)) {
  timer_ = loop_.AddTimer(
      period, [this] { PublishNow(); }, /*repeating=*/true);
  PublishNow();
}

ConfigPublisher::~ConfigPublisher() { loop_.CancelTimer(timer_); }

void ConfigPublisher::PublishNow() {
  avc::config_t config{};
  config.service = service_;
  config.sequence = 1;
  config.format = "toml";
  config.text = text_;
  config.sha256 = sha256_;
  try {
    bus_.Publish(channels::kConfig, config);
  } catch (const BusError& e) {
    log::Warn("configuration not published: {}", e.what());
  }
}

}  // namespace avc::bus
