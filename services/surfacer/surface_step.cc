#include "services/surfacer/surface_step.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/geometry/mesh_io.h"
#include "core/ppr/octree_voxels.h"
#include "core/stage/stage_names.h"
#include "core/surface/mesh_topology.h"
#include "core/surface/surface_images_io.h"
#include "core/traits/plant_traits.h"
#include "core/traits/traits_writer.h"
#include "core/util/file_io.h"
#include "services/builder/soil_level.h"
#include "services/clusterer/cluster_step.h"
#include "services/surfacer/plant_base.h"
#include "services/surfacer/surface_clusters.h"
#include "services/surfacer/surfacer_options.h"

namespace avc::surfacer {
namespace {

namespace fs = std::filesystem;

// What the surfacer made of the clusters (the scan report's "surface"), and what it warned of.
nlohmann::ordered_json SurfaceSummary(const surface::SurfaceReport& made) {
  return {{"clusters", made.clusters},
          {"points_used", made.used_points},
          {"points_left_out", made.points_left_out},
          {"cells", made.cells},
          {"cells_split_by_phase3", made.cell_islands},
          {"image_views", made.image_views},
          {"grown_vertices", made.grown_vertices},
          {"stitch_faces", made.stitching.faces},
          {"area_m2_after_phase",
           {{"1", made.area_triangulated},
            {"2", made.area_grown},
            {"3", made.area_modified},
            {"4", made.area}}},
          {"faces", made.faces},
          {"components", made.components},
          {"warnings", made.warnings}};
}

// Stems and siliques from the proxy's thin parts (core/surface/thin_organs.h), labelled as one
// more cluster; the traits and the summary are measured again on the whole mesh.
void AddThinOrganSurfaces(SurfacerResult& surface, const mvs::MvsBounds& proxy,
                          const SurfacerOptions& options) {
  int32_t label = 0;
  for (int32_t existing : surface.mesh.face_labels) label = std::max(label, existing + 1);
  const size_t added = surface::AddThinOrgans(surface.mesh, proxy.occupied_centres,
                                              proxy.voxel_size, options.thin_organs, label);
  if (added == 0) return;
  surface.traits = traits::MeasureTraits(surface.mesh, options.traits);
  surface.report.faces = surface.mesh.faces.size();
  surface::FaceComponents(surface.mesh, &surface.report.components);
}

}  // namespace

void SurfaceModel(const fs::path& model_dir, const fs::path& output_dir,
                  const SurfacerOptions& given) {
  const messages::ClustersContent clusters =
      clusterer::ReadClustersMessage(model_dir / stage::kClustersMessageFile);
  // The masks the build wrote drive Phase 2's growth (a model without them: the band growth).
  const surface::SurfaceImages images = surface::ReadSurfaceImages(model_dir);
  // Plant height from the soil surface the builder found, else from the proxy's base.
  SurfacerOptions options = given;
  const fs::path proxy_file = model_dir / "ppr.bt";
  const mvs::MvsBounds proxy =
      ppr::OccupiedVoxelsFromBinary(ReadFile(proxy_file), 0.0, proxy_file.string());
  options.traits.ground_z =
      PlantGroundZ(builder::SoilZ(builder::ReadSoilLevel(model_dir / "soil.json")), proxy);
  SurfacerResult surface = SurfaceClusters(clusters, options, &images);
  if (!surface.problem.empty()) {
    throw std::runtime_error("no surface could be made: " + surface.problem);
  }
  if (options.thin_organs.enabled) AddThinOrganSurfaces(surface, proxy, options);
  geometry::WriteMeshPly(output_dir / "mesh.ply", surface.mesh);
  traits::WriteTraitFiles(surface.traits, output_dir.string());
  WriteFileAtomically(output_dir / "surface.json", SurfaceSummary(surface.report).dump(2) + "\n");
}

stage::StageHandler SurfaceStageHandler(const SurfacerOptions& base) {
  return [base](const stage::StageWork& work) {
    SurfacerOptions options = base;
    SurfacerOptionTable().ApplyTexts(options, work.settings, "the surface job's settings");
    SurfaceModel(work.input_dir, work.output_dir, options);
  };
}

}  // namespace avc::surfacer
