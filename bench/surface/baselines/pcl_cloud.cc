#include "bench/surface/baselines/pcl_cloud.h"

#include <pcl/conversions.h>

namespace avc::surface::baselines {

pcl::PointCloud<pcl::PointNormal>::Ptr ToPclPointNormals(const geometry::PointCloud& cloud) {
  pcl::PointCloud<pcl::PointNormal>::Ptr result(new pcl::PointCloud<pcl::PointNormal>);
  result->reserve(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f& p = cloud.positions[i];
    const Eigen::Vector3f n = cloud.normals[i].normalized();
    pcl::PointNormal point;
    point.x = p.x(), point.y = p.y(), point.z = p.z();
    point.normal_x = n.x(), point.normal_y = n.y(), point.normal_z = n.z();
    point.curvature = 0.0f;
    result->push_back(point);
  }
  return result;
}

geometry::Mesh FromPclMesh(const pcl::PolygonMesh& mesh) {
  pcl::PointCloud<pcl::PointXYZ> vertices;
  pcl::fromPCLPointCloud2(mesh.cloud, vertices);
  geometry::Mesh result;
  result.vertices.reserve(vertices.size());
  for (const pcl::PointXYZ& p : vertices) result.vertices.emplace_back(p.x, p.y, p.z);
  for (const pcl::Vertices& polygon : mesh.polygons) {
    if (polygon.vertices.size() != 3) continue;
    result.faces.emplace_back(static_cast<int>(polygon.vertices[0]),
                              static_cast<int>(polygon.vertices[1]),
                              static_cast<int>(polygon.vertices[2]));
  }
  return result;
}

}  // namespace avc::surface::baselines
