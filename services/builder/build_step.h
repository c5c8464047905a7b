#pragma once

// The build stage of a scan, on files: masks, plant proxy and multi-view stereo from a scan
// folder (cameras.json and images/, as `avc scan` writes them) into a model folder (points.ply,
// ppr.bt, build.json, soil.json, the undistorted images and their masks). `avc scan` has it run by
// avc-builder over the bus (RegisterBuildStage); `avc replay` and the tests run it here. Same
// files and options in, same bytes out.

#include <filesystem>
#include <functional>
#include <string>

#include "core/stage/stage_server.h"
#include "services/builder/reconstruction.h"

namespace avc::builder {

// `report` (optional) hears a line per finished step ("undistort 34/34"). Throws
// std::invalid_argument or std::runtime_error naming the view or setting at fault.
void BuildModel(const std::filesystem::path& scan_dir, const std::filesystem::path& model_dir,
                const ReconstructOptions& options,
                const std::function<void(const std::string&)>& report = {});

// BuildModel on a stage job's folders, with `base` changed by the job's settings (ApplyOverride).
stage::StageHandler BuildStageHandler(const ReconstructOptions& base);

}  // namespace avc::builder
