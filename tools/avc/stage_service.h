#pragma once

// A stage service's serving side (avc builder, clusterer, surfacer, planner): publishes the
// configuration it runs with on CONFIG and serves the stage's jobs, naming that configuration
// in every result.

#include <memory>
#include <string>

#include "core/bus/service_runtime.h"
#include "core/stage/stage_server.h"

namespace avc::cli {

std::unique_ptr<stage::StageServer> ServeStage(bus::ServiceRuntime& runtime,
                                               const std::string& stage,
                                               stage::StageHandler handler,
                                               std::string config_text);

}  // namespace avc::cli
