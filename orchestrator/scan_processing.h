#pragma once

// The reconstruction a scan ends with, on a scan directory (images/ and cameras.json): MVS with
// the plant proxy (model/points.ply, ppr.bt, build.json, ...), merging and clustering
// (model/clusters.ply), the surface (model/mesh.ply). Each step reads the files the one before
// wrote, so a resumed scan can start at any of them; `avc scan` and `avc replay` run the same
// steps and so write the same bytes from the same images and cameras.

#include <filesystem>
#include <functional>
#include <string>

#include "core/messages/clusters_message.h"
#include "services/builder/reconstruction.h"
#include "services/clusterer/merge_and_cluster.h"
#include "services/surfacer/surface_clusters.h"

namespace avc::orchestrator {

// `report` (optional) hears a line per finished stage ("undistort 34/34").
void BuildModel(const std::filesystem::path& scan_dir, const std::filesystem::path& model_dir,
                const builder::ReconstructOptions& options,
                const std::function<void(const std::string&)>& report = {});

// Throws std::runtime_error when the points cannot be clustered.
messages::ClustersContent ClusterModel(const std::filesystem::path& model_dir,
                                       const clusterer::ClustererOptions& options);

// Throws std::runtime_error when no surface can be made.
surfacer::SurfacerResult SurfaceModel(const messages::ClustersContent& clusters,
                                      const std::filesystem::path& model_dir);

}  // namespace avc::orchestrator
