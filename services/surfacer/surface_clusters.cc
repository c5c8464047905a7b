#include "services/surfacer/surface_clusters.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/geometry/mesh_io.h"
#include "core/traits/traits_writer.h"
#include "core/util/validation.h"

namespace avc::surfacer {
namespace {

std::string JoinWarnings(const std::vector<std::string>& warnings) {
  std::string joined;
  for (const std::string& warning : warnings) joined += (joined.empty() ? "" : "; ") + warning;
  return joined;
}

}  // namespace

std::string SurfacerOptions::Validate() const {
  FirstProblem problem;
  problem.Include(surface.Validate());
  problem.Include(thin_organs.Validate());
  return problem.text();
}

SurfacerResult SurfaceClusters(const messages::ClustersContent& clusters,
                               const SurfacerOptions& options,
                               const surface::SurfaceImages* images) {
  SurfacerResult result;
  result.cloud_id = clusters.cloud_id;
  const std::string what = fmt::format("clusters of '{}'", clusters.cloud_id);
  if (!clusters.problem.empty()) {
    result.problem = fmt::format("{}: none made ({})", what, clusters.problem);
    return result;
  }
  surface::ClusteredPoints input;
  input.cloud = clusters.merged.cloud;
  input.clusters = clusters.clusters;
  try {
    surface::SurfaceResult surface = surface::ReconstructSurface(input, options.surface, images);
    result.mesh = std::move(surface.mesh);
    result.report = std::move(surface.report);
    result.traits = traits::MeasureTraits(result.mesh, options.traits);
  } catch (const std::invalid_argument& error) {
    result.problem = fmt::format("{}: {}", what, error.what());
    return result;
  }
  if (result.mesh.faces.empty()) {
    const std::string why = JoinWarnings(result.report.warnings);
    result.problem = fmt::format("{}: no surface could be made{}", what,
                                 why.empty() ? std::string() : " (" + why + ")");
  }
  return result;
}

void WriteSurfacerFiles(const SurfacerResult& result, const std::filesystem::path& directory) {
  std::filesystem::create_directories(directory);
  geometry::WriteMeshPly(directory / "mesh.ply", result.mesh);
  traits::WriteTraitFiles(result.traits, directory.string());
}

}  // namespace avc::surfacer
