#include "bench/surface/baselines/greedy_projection.h"

#include <fmt/format.h>
#include <pcl/search/kdtree.h>
#include <pcl/surface/gp3.h>

#include <numbers>
#include <stdexcept>

#include "bench/surface/baselines/baseline_input.h"
#include "bench/surface/baselines/pcl_cloud.h"
#include "core/surface/mesh_topology.h"

namespace avc::surface::baselines {
namespace {

constexpr const char* kGreedyProjection = "greedy projection baseline";

double Radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

geometry::Mesh GreedyProjection(const geometry::PointCloud& cloud,
                                const GreedyProjectionOptions& options) {
  CheckBaselineInput(cloud, kGreedyProjection, /*require_normals=*/true);
  if (!(options.radius_factor > 0.0) || !(options.mu > 0.0) || options.max_neighbours < 3) {
    throw std::invalid_argument(fmt::format(
        "{}: radius_factor and mu must be > 0 and max_neighbours >= 3", kGreedyProjection));
  }
  const double spacing = ResolveSpacing(cloud, options.spacing, kGreedyProjection);
  const pcl::PointCloud<pcl::PointNormal>::Ptr points = ToPclPointNormals(cloud);
  pcl::search::KdTree<pcl::PointNormal>::Ptr tree(new pcl::search::KdTree<pcl::PointNormal>);
  tree->setInputCloud(points);
  pcl::GreedyProjectionTriangulation<pcl::PointNormal> triangulation;
  triangulation.setSearchRadius(options.radius_factor * spacing);
  triangulation.setMu(options.mu);
  triangulation.setMaximumNearestNeighbors(options.max_neighbours);
  triangulation.setMaximumSurfaceAngle(Radians(options.max_surface_angle_deg));
  triangulation.setMinimumAngle(Radians(options.min_angle_deg));
  triangulation.setMaximumAngle(Radians(options.max_angle_deg));
  triangulation.setNormalConsistency(true);  // the normals are oriented (from the scan)
  triangulation.setConsistentVertexOrdering(true);
  triangulation.setInputCloud(points);
  triangulation.setSearchMethod(tree);
  pcl::PolygonMesh pcl_mesh;
  triangulation.reconstruct(pcl_mesh);
  geometry::Mesh mesh = FromPclMesh(pcl_mesh);
  RemoveUnusedVertices(mesh);  // PCL keeps every input point, used or not
  return mesh;
}

}  // namespace avc::surface::baselines
