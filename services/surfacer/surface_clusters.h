#pragma once

// The surfacer's work (paper §4), the same offline and on the bus (surfacer_node.h): the
// clusterer's merged, clustered points triangulated into one mesh (core/surface, Algorithm 3)
// and the plant's traits measured on it (core/traits).

#include <filesystem>
#include <string>

#include "core/geometry/mesh.h"
#include "core/messages/clusters_message.h"
#include "core/surface/image_evidence.h"
#include "core/surface/surface_options.h"
#include "core/surface/surface_reconstruction.h"
#include "core/surface/thin_organs.h"
#include "core/traits/plant_traits.h"

namespace avc::surfacer {

struct SurfacerOptions {
  surface::SurfaceOptions surface;
  traits::TraitOptions traits;
  // Used where the plant proxy is at hand (SurfaceModel): off by default.
  surface::ThinOrganOptions thin_organs;

  // Empty when usable; else the first bad setting.
  std::string Validate() const;
};

struct SurfacerResult {
  std::string cloud_id;  // the clusters' cloud id this answers
  // Empty when a surface was made; else why not (the clusters' own problem, bad points, bad
  // options, no cluster that could be triangulated). The mesh may then be empty.
  std::string problem;
  geometry::Mesh mesh;  // face_labels: cluster ids; colours: the points' when they have them
  surface::SurfaceReport report;
  traits::PlantTraits traits;
};

// Never throws for bad data: every problem ends up in `problem`. images: the scan's views with
// plant masks, for Phase 2's image-driven growth (nullptr: the band growth without images).
SurfacerResult SurfaceClusters(const messages::ClustersContent& clusters,
                               const SurfacerOptions& options = {},
                               const surface::SurfaceImages* images = nullptr);

// Writes directory/mesh.ply (binary; per-face `label` = cluster id, per-vertex colours),
// directory/traits.csv and directory/traits.json. Throws std::runtime_error naming the file when
// it cannot be written.
void WriteSurfacerFiles(const SurfacerResult& result, const std::filesystem::path& directory);

}  // namespace avc::surfacer
