#pragma once

// Meshes, clouds and cameras with known answers for the evaluation tests.

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>

#include "core/camera/pinhole_camera.h"
#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::eval::test {

// An axis-aligned rectangle [x0, x1] x [y0, y1] at height z, facing +z, split into n x n quads.
inline geometry::Mesh Rectangle(double x0, double x1, double y0, double y1, double z, int n = 1,
                                int32_t label = geometry::labels::kLeafBase) {
  geometry::Mesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      mesh.vertices.emplace_back(static_cast<float>(x0 + (x1 - x0) * i / n),
                                 static_cast<float>(y0 + (y1 - y0) * j / n), static_cast<float>(z));
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      mesh.faces.emplace_back(a, b, d);
      mesh.faces.emplace_back(a, d, c);
    }
  }
  mesh.face_labels.assign(mesh.faces.size(), label);
  return mesh;
}

// An icosphere of the given radius (subdivided `levels` times, 20 * 4^levels faces).
inline geometry::Mesh Sphere(double radius, int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                    {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                    {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (Eigen::Vector3d& p : v) p.normalize();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      const auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return midpoints[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<Eigen::Vector3i> finer;
    for (const Eigen::Vector3i& face : f) {
      const int ab = midpoint(face[0], face[1]);
      const int bc = midpoint(face[1], face[2]);
      const int ca = midpoint(face[2], face[0]);
      finer.emplace_back(face[0], ab, ca);
      finer.emplace_back(face[1], bc, ab);
      finer.emplace_back(face[2], ca, bc);
      finer.emplace_back(ab, bc, ca);
    }
    f = std::move(finer);
  }
  geometry::Mesh mesh;
  for (const Eigen::Vector3d& p : v) mesh.vertices.push_back((p * radius).cast<float>());
  mesh.faces = f;
  return mesh;
}

// A regular grid of points x0 + (i + 0.5) * step over [x0, x1) x [y0, y1) at height z.
inline geometry::PointCloud Grid(double x0, double x1, double y0, double y1, double z,
                                 double step) {
  geometry::PointCloud cloud;
  const int nx = static_cast<int>(std::lround((x1 - x0) / step));
  const int ny = static_cast<int>(std::lround((y1 - y0) / step));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      cloud.positions.emplace_back(static_cast<float>(x0 + (i + 0.5) * step),
                                   static_cast<float>(y0 + (j + 0.5) * step),
                                   static_cast<float>(z));
    }
  }
  return cloud;
}

// A 640 x 480 pinhole camera (f = 500 px) at `centre` looking at `target`, image "up" towards
// `up` (OpenCV axes: x right, y down, z forward).
inline camera::Camera LookAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& target,
                             const Eigen::Vector3d& up = Eigen::Vector3d::UnitY()) {
  camera::Camera camera;
  camera.intrinsics.width = 640;
  camera.intrinsics.height = 480;
  camera.intrinsics.fx = camera.intrinsics.fy = 500;
  camera.intrinsics.cx = 319.5;
  camera.intrinsics.cy = 239.5;
  const Eigen::Vector3d z = (target - centre).normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R_world_cam;
  R_world_cam << x, y, z;
  camera.T_cam_world.linear() = R_world_cam.transpose();
  camera.T_cam_world.translation() = -R_world_cam.transpose() * centre;
  return camera;
}

// Calls visit(row, column, hit) for every pixel whose ray (through the pixel's centre) meets the
// horizontal plane z = height in front of the camera, with the point it meets.
template <typename Visit>
void ForEachPlaneHit(const camera::Camera& camera, double height, Visit visit) {
  const camera::Intrinsics& k = camera.intrinsics;
  const Eigen::Isometry3d world_from_camera = camera.T_cam_world.inverse();
  const Eigen::Vector3d centre = world_from_camera.translation();
  for (int row = 0; row < k.height; ++row) {
    for (int column = 0; column < k.width; ++column) {
      const Eigen::Vector3d ray = world_from_camera.linear() *
                                  Eigen::Vector3d((column - k.cx) / k.fx, (row - k.cy) / k.fy, 1.0);
      const double along = (height - centre.z()) / ray.z();
      if (!(along > 0.0)) continue;
      visit(row, column, Eigen::Vector3d(centre + along * ray));
    }
  }
}

}  // namespace avc::eval::test
