#include "bench/surface/baselines/poisson_trimmed.h"

#include <fmt/format.h>
#include <pcl/surface/poisson.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/surface/baselines/baseline_input.h"
#include "bench/surface/baselines/pcl_cloud.h"
#include "bench/surface/baselines/trim_to_data.h"

namespace avc::surface::baselines {
namespace {

constexpr const char* kPoisson = "Poisson baseline";

int AutomaticDepth(const geometry::PointCloud& cloud, double spacing) {
  Eigen::Vector3f low = cloud.positions.front();
  Eigen::Vector3f high = low;
  for (const Eigen::Vector3f& p : cloud.positions) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double cube = 1.1 * static_cast<double>((high - low).maxCoeff());
  const int depth = static_cast<int>(std::ceil(std::log2(std::max(cube / spacing, 1.0))));
  return std::clamp(depth, 6, 10);
}

}  // namespace

geometry::Mesh PoissonTrimmed(const geometry::PointCloud& cloud, const PoissonOptions& options) {
  CheckBaselineInput(cloud, kPoisson, /*require_normals=*/true);
  if (!(options.trim_factor > 0.0) || options.depth > 12) {
    throw std::invalid_argument(
        fmt::format("{}: trim_factor must be > 0 and depth <= 12 (got {}, {})", kPoisson,
                    options.trim_factor, options.depth));
  }
  const double spacing = ResolveSpacing(cloud, options.spacing, kPoisson);
  pcl::Poisson<pcl::PointNormal> poisson;
  poisson.setInputCloud(ToPclPointNormals(cloud));
  poisson.setDepth(options.depth > 0 ? options.depth : AutomaticDepth(cloud, spacing));
  poisson.setThreads(1);  // deterministic
  pcl::PolygonMesh pcl_mesh;
  poisson.reconstruct(pcl_mesh);
  geometry::Mesh mesh = FromPclMesh(pcl_mesh);
  TrimToData(mesh, cloud.positions, options.trim_factor * spacing);
  return mesh;
}

}  // namespace avc::surface::baselines
