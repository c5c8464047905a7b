#pragma once

// The surface-and-traits stage of a scan, on files: a model folder's clusters (clusters.lcm),
// the undistorted views and their masks (cameras.json, images/, masks/), the soil level
// (soil.json) and the plant proxy (ppr.bt) into mesh.ply, traits.csv, traits.json and
// surface.json (what the surfacer made: areas per phase, faces, warnings). `avc scan` has it run
// by avc-surfacer over the bus; `avc replay` and the tests run it here.

#include <filesystem>

#include "core/stage/stage_server.h"
#include "services/surfacer/surface_clusters.h"

namespace avc::surfacer {

// The traits' ground comes from the model's soil (or proxy), whatever `options` say. Throws
// std::runtime_error naming the file, or why no surface could be made.
void SurfaceModel(const std::filesystem::path& model_dir, const std::filesystem::path& output_dir,
                  const SurfacerOptions& options = {});

// SurfaceModel on a stage job's folders, with `options` changed by the job's settings
// (surfacer_options.h).
stage::StageHandler SurfaceStageHandler(const SurfacerOptions& options);

}  // namespace avc::surfacer
