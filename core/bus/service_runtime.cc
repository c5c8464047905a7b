#include "core/bus/service_runtime.h"

#include <signal.h>

#include "core/util/log.h"

namespace avc::bus {

ServiceRuntime::ServiceRuntime(const std::string& service, const BusFlags& flags)
    : service_(service) {
  log::SetProcessName(service);
  bus_ = std::make_unique<Bus>(ResolveBusOptions(flags, service));
  bus_->AttachTo(loop_);
  heartbeat_ = std::make_unique<HeartbeatPublisher>(*bus_, loop_, service);
  loop_.QuitOnTerminationSignals([this](int signo) {
    log::Info("{} received, stopping", signo == SIGTERM ? "SIGTERM" : "SIGINT");
    heartbeat_->Set(ServiceState::kStopping, "stopping");
    if (on_stop_) on_stop_();
  });
}

const std::string& ServiceRuntime::PublishConfig(std::string toml_text) {
  config_ = std::make_unique<ConfigPublisher>(*bus_, loop_, service_, std::move(toml_text));
  return config_->sha256();
}

int ServiceRuntime::Run() {
  log::Info("running on cell '{}' (control {}, bulk {})", bus_->cell(), bus_->options().control_url,
            bus_->options().bulk_url.empty() ? "shared" : bus_->options().bulk_url);
  return loop_.Run();
}

}  // namespace avc::bus
