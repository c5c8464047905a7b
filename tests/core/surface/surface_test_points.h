#pragma once

// Point sets with known surfaces for the surfacer tests: analytic sheets and points sampled on
// the leaves of the simulated plants. Deterministic (own mapping of std::mt19937_64 bits).

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "core/geometry/mesh.h"
#include "core/surface/clustered_points.h"
#include "core/util/ordered_draws.h"

namespace avc::surface::test {

inline double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Approximately standard normal (Irwin-Hall sum of four uniforms).
inline double Gaussian(std::mt19937_64& rng) {
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += Uniform(rng);
  return (sum - 2.0) * std::sqrt(3.0);
}

inline void AddPoint(ClusteredPoints& set, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                     int32_t cluster) {
  set.cloud.positions.push_back(p.cast<float>());
  set.cloud.normals.push_back(n.normalized().cast<float>());
  set.clusters.push_back(cluster);
}

// n points filling a disc of the given radius in the z = 0 plane, facing +z, on Vogel's
// sunflower spiral (even spacing, like voxel-averaged merged points), all in cluster 0.
inline ClusteredPoints SpiralDisc(double radius, int n) {
  ClusteredPoints set;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double r = radius * std::sqrt((i + 0.5) / n);
    const double phi = golden * i;
    AddPoint(set, {r * std::cos(phi), r * std::sin(phi), 0.0}, Eigen::Vector3d::UnitZ(), 0);
  }
  return set;
}

// n points uniformly at random on a disc, cluster 0.
inline ClusteredPoints RandomDisc(double radius, int n, uint64_t seed) {
  ClusteredPoints set;
  std::mt19937_64 rng(seed);
  for (int i = 0; i < n; ++i) {
    const double r = radius * std::sqrt(Uniform(rng));
    const double phi = 2.0 * std::numbers::pi * Uniform(rng);
    AddPoint(set, {r * std::cos(phi), r * std::sin(phi), 0.0}, Eigen::Vector3d::UnitZ(), 0);
  }
  return set;
}

// n points uniformly at random on a section of a cylinder of radius r about the y axis,
// spanning angle (radians) round it and height along it, normals pointing outwards (the true
// ones); positions off the cylinder by noise (m) per axis.
inline ClusteredPoints CylinderSheet(double r, double angle, double height, int n, uint64_t seed,
                                     double noise = 0.0) {
  ClusteredPoints set;
  std::mt19937_64 rng(seed);
  for (int i = 0; i < n; ++i) {
    const double phi = (Uniform(rng) - 0.5) * angle;
    const double y = (Uniform(rng) - 0.5) * height;
    const Eigen::Vector3d normal(std::sin(phi), 0.0, std::cos(phi));
    Eigen::Vector3d p = r * normal + Eigen::Vector3d(0.0, y, 0.0);
    if (noise > 0.0) p += noise * util::DrawVector3<Eigen::Vector3d>([&] { return Gaussian(rng); });
    AddPoint(set, p, normal, 0);
  }
  return set;
}

// Points sampled uniformly by area on the faces of mesh with a leaf label (one-sided),
// position noise sigma per axis; clusters = the leaf label - kLeafBase. *leaves receives the
// leaf faces as a mesh (with their labels): the ground truth.
inline ClusteredPoints SampleLeaves(const geometry::Mesh& mesh, int n, double sigma, uint64_t seed,
                                    geometry::Mesh* leaves) {
  std::vector<size_t> faces;
  std::vector<double> cumulative;
  double area = 0.0;
  *leaves = geometry::Mesh();
  leaves->vertices = mesh.vertices;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!geometry::labels::IsLeaf(mesh.face_labels[f])) continue;
    const Eigen::Vector3i& t = mesh.faces[f];
    leaves->faces.push_back(t);
    leaves->face_labels.push_back(mesh.face_labels[f]);
    const double a = 0.5 * static_cast<double>((mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                                   .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                                                   .norm());
    if (!(a > 0.0)) continue;
    area += a;
    faces.push_back(f);
    cumulative.push_back(area);
  }
  ClusteredPoints set;
  std::mt19937_64 rng(seed);
  for (int s = 0; s < n; ++s) {
    const double pick = Uniform(rng) * area;
    size_t k = static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
                                   cumulative.begin());
    k = std::min(k, faces.size() - 1);
    const Eigen::Vector3i& t = mesh.faces[faces[k]];
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[t[2]].cast<double>();
    const double r1 = std::sqrt(Uniform(rng));
    const double r2 = Uniform(rng);
    Eigen::Vector3d p = (1.0 - r1) * a + r1 * (1.0 - r2) * b + r1 * r2 * c;
    p += sigma * util::DrawVector3<Eigen::Vector3d>([&] { return Gaussian(rng); });
    AddPoint(set, p, (b - a).cross(c - a),
             mesh.face_labels[faces[k]] - geometry::labels::kLeafBase);
  }
  return set;
}

}  // namespace avc::surface::test
