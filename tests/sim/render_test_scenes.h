#pragma once

// Small scenes, cameras and a brute-force ray caster for the renderer's tests.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "sim/scene/scene.h"

namespace avc::sim::render_test {

// 640x480 camera with (or without) a realistic amount of distortion.
inline camera::Intrinsics TestIntrinsics(bool distorted, int width = 640, int height = 480) {
  camera::Intrinsics k;
  k.width = width;
  k.height = height;
  k.fx = 0.95 * width;
  k.fy = 0.95 * width * 1.002;
  k.cx = 0.5 * width - 0.5 + 3.3;
  k.cy = 0.5 * height - 0.5 - 2.1;
  if (distorted) k.distortion = {-0.18, 0.07, 0.0012, -0.0009, -0.012};
  return k;
}

// Camera at centre looking at target, image y pointing down along -up.
inline Eigen::Isometry3d LookAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& target,
                                const Eigen::Vector3d& up = Eigen::Vector3d::UnitZ()) {
  const Eigen::Vector3d z = (target - centre).normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R_world_cam;
  R_world_cam << x, y, z;
  Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
  T_world_cam.linear() = R_world_cam;
  T_world_cam.translation() = centre;
  return T_world_cam.inverse();
}

// A material whose albedo is the same everywhere (uv_extent 0 maps every uv to one texel).
inline Material UniformMaterial(const Eigen::Vector3f& rgb, const std::string& name = "uniform") {
  Material m;
  m.name = name;
  m.kind = MaterialKind::kPlain;
  m.base_rgb = rgb;
  m.variation = 0;
  m.uv_extent = Eigen::Vector2f::Zero();
  return m;
}

// A textured material (uvs in metres).
inline Material TexturedMaterial(uint32_t seed) {
  Material m;
  m.name = "textured";
  m.kind = MaterialKind::kPlain;
  m.base_rgb = {0.4f, 0.5f, 0.3f};
  m.variation = 0.2f;
  m.detail_scale = 0.3f;
  m.seed = seed;
  return m;
}

// Appends a parallelogram corner + s*edge_u + t*edge_v (s, t in 0..1) cut into cells x cells
// squares of two triangles, counter-clockwise seen from edge_u x edge_v. uvs in metres.
inline void AddQuad(geometry::Mesh* mesh, const Eigen::Vector3f& corner,
                    const Eigen::Vector3f& edge_u, const Eigen::Vector3f& edge_v, int cells,
                    int32_t label, int32_t material) {
  const int base = static_cast<int>(mesh->vertices.size());
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const float s = static_cast<float>(i) / cells, t = static_cast<float>(j) / cells;
      mesh->vertices.push_back(corner + s * edge_u + t * edge_v);
      mesh->uvs.emplace_back(s * edge_u.norm(), t * edge_v.norm());
    }
  }
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const int a = base + j * (cells + 1) + i;
      const int b = a + 1, c = a + cells + 1, d = c + 1;
      mesh->faces.emplace_back(a, b, d);
      mesh->faces.emplace_back(a, d, c);
      mesh->face_labels.insert(mesh->face_labels.end(), 2, label);
      mesh->face_materials.insert(mesh->face_materials.end(), 2, material);
    }
  }
}

// Appends a UV sphere.
inline void AddSphere(geometry::Mesh* mesh, const Eigen::Vector3f& centre, float radius, int slices,
                      int stacks, int32_t label, int32_t material) {
  const int base = static_cast<int>(mesh->vertices.size());
  for (int j = 0; j <= stacks; ++j) {
    const float theta = static_cast<float>(M_PI) * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const float phi = 2.0f * static_cast<float>(M_PI) * i / slices;
      mesh->vertices.push_back(centre + radius * Eigen::Vector3f(std::sin(theta) * std::cos(phi),
                                                                 std::sin(theta) * std::sin(phi),
                                                                 std::cos(theta)));
      mesh->uvs.emplace_back(phi * radius, theta * radius);
    }
  }
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const int a = base + j * (slices + 1) + i;
      const int b = a + 1, c = a + slices + 1, d = c + 1;
      if (j > 0) {
        mesh->faces.emplace_back(a, c, b);
        mesh->face_labels.push_back(label);
        mesh->face_materials.push_back(material);
      }
      if (j + 1 < stacks) {
        mesh->faces.emplace_back(b, c, d);
        mesh->face_labels.push_back(label);
        mesh->face_materials.push_back(material);
      }
    }
  }
}

// Gives every face its own label (face index + 1) so a label image names faces.
inline void LabelFacesByIndex(geometry::Mesh* mesh) {
  for (size_t i = 0; i < mesh->faces.size(); ++i)
    mesh->face_labels[i] = static_cast<int32_t>(i + 1);
}

struct RayHit {
  int face = -1;
  double distance = 0;  // along the unit ray
  Eigen::Vector3d barycentric;
};

// Möller–Trumbore against every face, in double; nearest hit.
inline std::optional<RayHit> CastRay(const geometry::Mesh& mesh, const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& direction) {
  std::optional<RayHit> best;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3d a = mesh.vertices[mesh.faces[f][0]].cast<double>();
    const Eigen::Vector3d e1 = mesh.vertices[mesh.faces[f][1]].cast<double>() - a;
    const Eigen::Vector3d e2 = mesh.vertices[mesh.faces[f][2]].cast<double>() - a;
    const Eigen::Vector3d p = direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-18) continue;
    const Eigen::Vector3d s = origin - a;
    const double u = s.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = direction.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const double t = e2.dot(q) / det;
    if (t <= 0 || (best && t >= best->distance)) continue;
    best = RayHit{static_cast<int>(f), t, Eigen::Vector3d(1 - u - v, u, v)};
  }
  return best;
}

}  // namespace avc::sim::render_test
