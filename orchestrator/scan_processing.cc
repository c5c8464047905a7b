#include "orchestrator/scan_processing.h"

#include <stdexcept>

#include "core/dataset/dataset_reader.h"
#include "core/geometry/mesh_io.h"
#include "core/ppr/octree_voxels.h"
#include "core/surface/surface_images_io.h"
#include "core/util/file_io.h"
#include "services/builder/build_report.h"
#include "services/builder/reconstruction_output.h"
#include "services/builder/soil_level.h"
#include "services/clusterer/cluster_folder.h"
#include "services/clusterer/clusters_ply.h"
#include "services/surfacer/plant_base.h"

namespace avc::orchestrator {

void BuildModel(const std::filesystem::path& scan_dir, const std::filesystem::path& model_dir,
                const builder::ReconstructOptions& options,
                const std::function<void(const std::string&)>& report) {
  dataset::ViewSet set = dataset::ReadDataset(scan_dir);
  const builder::Reconstruction reconstruction =
      builder::Reconstruct(set, options, [&](const std::string& stage, size_t done, size_t total) {
        if (report && done == total)
          report(stage + " " + std::to_string(done) + "/" + std::to_string(total));
      });
  const builder::BuildReport build_report =
      builder::MakeBuildReport(reconstruction, options.method, set.ground_truth_mesh);
  builder::WriteReconstruction(model_dir, set, reconstruction, build_report, /*overwrite=*/true);
}

messages::ClustersContent ClusterModel(const std::filesystem::path& model_dir,
                                       const clusterer::ClustererOptions& options) {
  messages::ClustersContent clusters =
      clusterer::ClusterFolderFiles(model_dir / "points.ply", model_dir / "ppr.bt", options);
  if (!clusters.problem.empty()) {
    throw std::runtime_error("the points could not be clustered: " + clusters.problem);
  }
  clusterer::WriteClustersPly(model_dir / "clusters.ply", clusters);
  return clusters;
}

surfacer::SurfacerResult SurfaceModel(const messages::ClustersContent& clusters,
                                      const std::filesystem::path& model_dir) {
  // The masks BuildModel wrote drive Phase 2's growth (a model without them: the band growth).
  const surface::SurfaceImages images = surface::ReadSurfaceImages(model_dir);
  // Plant height from the soil surface the builder found, else from the proxy's base.
  surfacer::SurfacerOptions options;
  const std::filesystem::path proxy_file = model_dir / "ppr.bt";
  options.traits.ground_z = surfacer::PlantGroundZ(
      builder::SoilZ(builder::ReadSoilLevel(model_dir / "soil.json")),
      ppr::OccupiedVoxelsFromBinary(ReadFile(proxy_file), 0.0, proxy_file.string()));
  surfacer::SurfacerResult surface = surfacer::SurfaceClusters(clusters, options, &images);
  if (!surface.problem.empty()) {
    throw std::runtime_error("no surface could be made: " + surface.problem);
  }
  geometry::WriteMeshPly(model_dir / "mesh.ply", surface.mesh);
  return surface;
}

}  // namespace avc::orchestrator
