#pragma once

// Conversions between our clouds and meshes and PCL's, for the PCL baselines only.

#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::surface::baselines {

// Positions and normals (the cloud must have normals).
pcl::PointCloud<pcl::PointNormal>::Ptr ToPclPointNormals(const geometry::PointCloud& cloud);

// Triangles of a PCL polygon mesh (other polygons are skipped) with its vertices.
geometry::Mesh FromPclMesh(const pcl::PolygonMesh& mesh);

}  // namespace avc::surface::baselines
