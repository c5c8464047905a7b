#include "tools/avc/stage_service.h"

namespace avc::cli {

std::unique_ptr<stage::StageServer> ServeStage(bus::ServiceRuntime& runtime,
                                               const std::string& stage,
                                               stage::StageHandler handler,
                                               std::string config_text) {
  stage::StageServerOptions options;
  options.service = runtime.service();
  options.stage = stage;
  options.handler = std::move(handler);
  options.config_sha256 = runtime.PublishConfig(config_text);
  options.config_text = std::move(config_text);
  return std::make_unique<stage::StageServer>(runtime.bus(), runtime.loop(), std::move(options));
}

}  // namespace avc::cli
