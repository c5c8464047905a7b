#pragma once

// A reconstruction on disk, with a scan directory's file names: ppr.bt (the plant proxy, for
// octovis), points.ply (MVS points with confidence and view indices), masks/<image>.png (the
// masks used), images/<image>.jpg (the undistorted images, for the surfacer's colour
// agreement), cameras.json (the cameras as used, distortion removed) and build.json (the run's
// report). Later stages add merged.ply, clusters.ply, mesh.ply and traits.csv beside them.

#include <filesystem>
#include <string>
#include <vector>

#include "core/dataset/view.h"
#include "services/builder/build_report.h"
#include "services/builder/reconstruction.h"

namespace avc::builder {

// `requested` when given, else "<dataset folder name>-reconstruction" in the current directory,
// with "-2", "-3", ... appended while that name is taken by a non-empty directory.
std::filesystem::path ChooseOutputDirectory(const std::filesystem::path& dataset_dir,
                                            const std::filesystem::path& requested);

// Writes the files (creating `dir`) and returns their names relative to it. Refuses (throws
// std::runtime_error) to replace an existing ppr.bt or points.ply unless `overwrite`, so an
// earlier result is never lost by accident.
std::vector<std::string> WriteReconstruction(const std::filesystem::path& dir,
                                             const dataset::ViewSet& set,
                                             const Reconstruction& reconstruction,
                                             const BuildReport& report, bool overwrite);

}  // namespace avc::builder
