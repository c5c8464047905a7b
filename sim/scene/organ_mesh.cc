#include "sim/scene/organ_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace avc::sim {
namespace {

float SmoothStep(float lo, float hi, float x) {
  const float t = std::clamp((x - lo) / (hi - lo), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Local half-width as a fraction of the greatest, at u along the leaf. Never zero, so the tip
// has no degenerate triangles.
float OutlineWidth(LeafOutline outline, float u) {
  switch (outline) {
    case LeafOutline::kLanceolate:
      return std::max(0.03f, std::pow(1.0f - u, 0.85f) * (0.7f + 0.3f * SmoothStep(0, 0.15f, u)));
    case LeafOutline::kOvate:
      return std::max(0.06f, std::pow(std::sin(kPi * std::pow(u, 0.75f)), 0.8f));
    case LeafOutline::kStrap:
      return std::max(0.03f, (0.5f + 0.5f * SmoothStep(0, 0.25f, u)) *
                                 std::sqrt(std::max(0.0f, 1.0f - u * u * u)));
    case LeafOutline::kElliptic:
      return std::max(0.04f, std::pow(std::sin(kPi * std::pow(u, 0.85f)), 0.9f));
  }
  return 1.0f;
}

// The tube centre line resampled at even arc length, with radii.
void ResampleTube(const TubeSpec& tube, float step, std::vector<Eigen::Vector3f>* points,
                  std::vector<float>* radii) {
  std::vector<float> cumulative(1, 0.0f);
  for (size_t k = 1; k < tube.points.size(); ++k) {
    cumulative.push_back(cumulative.back() + (tube.points[k] - tube.points[k - 1]).norm());
  }
  const float total = cumulative.back();
  const int segments = std::max(1, static_cast<int>(std::ceil(total / step)));
  points->clear();
  radii->clear();
  size_t k = 1;
  for (int i = 0; i <= segments; ++i) {
    const float s = total * static_cast<float>(i) / static_cast<float>(segments);
    while (k + 1 < tube.points.size() && cumulative[k] < s) ++k;
    const float span = cumulative[k] - cumulative[k - 1];
    const float t = span > 0 ? std::clamp((s - cumulative[k - 1]) / span, 0.0f, 1.0f) : 0.0f;
    points->push_back(tube.points[k - 1] + t * (tube.points[k] - tube.points[k - 1]));
    radii->push_back(tube.radii[k - 1] + t * (tube.radii[k] - tube.radii[k - 1]));
  }
}

int TubeSegments(const TubeSpec& tube, float step) {
  float total = 0;
  for (size_t k = 1; k < tube.points.size(); ++k) {
    total += (tube.points[k] - tube.points[k - 1]).norm();
  }
  return std::max(1, static_cast<int>(std::ceil(total / step)));
}

// Any unit vector perpendicular to direction.
Eigen::Vector3f Perpendicular(const Eigen::Vector3f& direction) {
  const Eigen::Vector3f axis =
      std::abs(direction.z()) < 0.9f ? Eigen::Vector3f::UnitZ() : Eigen::Vector3f::UnitX();
  return direction.cross(axis).normalized();
}

// The shortest rotation taking direction `from` to direction `to`, computed as Eigen's
// Quaternion::FromTwoVectors does (so the meshes keep their bytes) but without the SVD that one
// instantiates for opposite directions, which cost seconds of compile time: a half turn about a
// perpendicular axis does there.
Eigen::Quaternionf RotationBetween(const Eigen::Vector3f& from, const Eigen::Vector3f& to) {
  const Eigen::Vector3f v0 = from.normalized();
  const Eigen::Vector3f v1 = to.normalized();
  const float c = v1.dot(v0);
  if (c < -1.0f + Eigen::NumTraits<float>::dummy_precision()) {
    const Eigen::Vector3f axis = Perpendicular(v0);
    return Eigen::Quaternionf(0.0f, axis.x(), axis.y(), axis.z());
  }
  const Eigen::Vector3f axis = v0.cross(v1);
  const float s = std::sqrt((1.0f + c) * 2.0f);
  const float inverse_s = 1.0f / s;
  Eigen::Quaternionf rotation;
  rotation.vec() = axis * inverse_s;
  rotation.w() = s * 0.5f;
  return rotation;
}

}  // namespace

MeshResolution ResolutionFor(int leaf_segments, float leaf_across_ratio) {
  MeshResolution r;
  r.leaf_along = std::max(2, leaf_segments);
  const int across = static_cast<int>(std::lround(leaf_segments * leaf_across_ratio / 2.0f)) * 2;
  r.leaf_across = std::max(4, across);
  r.tube_around = std::clamp(leaf_segments / 3, 6, 32);
  r.tube_step = 0.25f / static_cast<float>(std::max(leaf_segments, 4));
  r.pot_around = std::clamp(3 * leaf_segments, 48, 192);
  r.soil_rings = std::clamp(leaf_segments / 3, 4, 24);
  return r;
}

size_t LeafTriangles(const MeshResolution& resolution) {
  return 2 * static_cast<size_t>(resolution.leaf_along) * resolution.leaf_across;
}

size_t TubeTriangles(const TubeSpec& tube, const MeshResolution& resolution) {
  const size_t around = resolution.tube_around;
  return 2 * around * TubeSegments(tube, resolution.tube_step) + around;
}

void AppendLeaf(const LeafSpec& leaf, const Eigen::Vector3f& offset,
                const MeshResolution& resolution, int32_t label, int32_t material,
                geometry::Mesh* mesh) {
  const int nu = resolution.leaf_along;
  const int nv = resolution.leaf_across;
  std::vector<Eigen::Vector3f> midrib;
  std::vector<Eigen::Vector3f> tangents;
  ArcCurve(leaf.base + offset, leaf.azimuth, leaf.elevation, leaf.droop, leaf.droop_power,
           leaf.side_bend, leaf.length, nu, &midrib, &tangents);
  const int first = static_cast<int>(mesh->vertices.size());
  for (int i = 0; i <= nu; ++i) {
    const float u = static_cast<float>(i) / static_cast<float>(nu);
    const Eigen::Vector3f& t = tangents[i];
    // Side and upper-side normal before twist: the side stays horizontal.
    const float heading = leaf.azimuth + leaf.side_bend * u;
    const Eigen::Vector3f side0(-std::sin(heading), std::cos(heading), 0.0f);
    const Eigen::Vector3f normal0 = t.cross(side0);
    const float twist = leaf.twist * u;
    const Eigen::Vector3f side = std::cos(twist) * side0 + std::sin(twist) * normal0;
    const Eigen::Vector3f normal = -std::sin(twist) * side0 + std::cos(twist) * normal0;
    const float width = leaf.half_width * OutlineWidth(leaf.outline, u);
    const float wave =
        leaf.wave_amplitude * std::sin(2.0f * kPi * (leaf.wave_count * u + leaf.wave_phase));
    for (int j = 0; j <= nv; ++j) {
      const float v = -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(nv);
      const float a = std::abs(v);
      const float lift = width * (leaf.fold * std::pow(a, leaf.fold_power) + wave * a * a);
      mesh->vertices.push_back(midrib[i] + side * (v * width) + normal * lift);
      mesh->uvs.emplace_back(u, v);
    }
  }
  const int row = nv + 1;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const int a = first + i * row + j;
      const int b = a + row;  // next along the leaf
      mesh->faces.emplace_back(a, b, b + 1);
      mesh->faces.emplace_back(a, b + 1, a + 1);
    }
  }
  const size_t added = 2 * static_cast<size_t>(nu) * nv;
  mesh->face_labels.insert(mesh->face_labels.end(), added, label);
  mesh->face_materials.insert(mesh->face_materials.end(), added, material);
}

void AppendTube(const TubeSpec& tube, const Eigen::Vector3f& offset,
                const MeshResolution& resolution, int32_t material, geometry::Mesh* mesh) {
  std::vector<Eigen::Vector3f> points;
  std::vector<float> radii;
  ResampleTube(tube, resolution.tube_step, &points, &radii);
  const int rings = static_cast<int>(points.size());
  const int around = resolution.tube_around;
  const int first = static_cast<int>(mesh->vertices.size());
  // Parallel-transported frame: the ring does not spin along the tube.
  Eigen::Vector3f tangent = (points[1] - points[0]).normalized();
  Eigen::Vector3f normal = Perpendicular(tangent);
  float along = 0;
  for (int k = 0; k < rings; ++k) {
    const Eigen::Vector3f next_tangent =
        (points[std::min(k + 1, rings - 1)] - points[std::max(k - 1, 0)]).normalized();
    const Eigen::Vector3f rotated = RotationBetween(tangent, next_tangent) * normal;
    tangent = next_tangent;
    normal = (rotated - rotated.dot(tangent) * tangent).normalized();
    const Eigen::Vector3f binormal = tangent.cross(normal);
    if (k > 0) along += (points[k] - points[k - 1]).norm();
    // around + 1 vertices: the seam is duplicated so uvs do not wrap inside a triangle.
    for (int j = 0; j <= around; ++j) {
      const float angle = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(around);
      const Eigen::Vector3f radial = std::cos(angle) * normal + std::sin(angle) * binormal;
      mesh->vertices.push_back(points[k] + offset + radii[k] * radial);
      mesh->uvs.emplace_back(angle * radii[k], along);
    }
  }
  const int row = around + 1;
  for (int k = 0; k + 1 < rings; ++k) {
    for (int j = 0; j < around; ++j) {
      const int a = first + k * row + j;
      const int b = a + row;
      mesh->faces.emplace_back(a, a + 1, b + 1);
      mesh->faces.emplace_back(a, b + 1, b);
    }
  }
  // A short cone closes the end.
  const int tip = static_cast<int>(mesh->vertices.size());
  mesh->vertices.push_back(points.back() + offset + tangent * radii.back());
  mesh->uvs.emplace_back(0.0f, along + radii.back());
  const int last = first + (rings - 1) * row;
  for (int j = 0; j < around; ++j) mesh->faces.emplace_back(last + j, last + j + 1, tip);
  const size_t added = 2 * static_cast<size_t>(around) * (rings - 1) + around;
  mesh->face_labels.insert(mesh->face_labels.end(), added, tube.label);
  mesh->face_materials.insert(mesh->face_materials.end(), added, material);
}

}  // namespace avc::sim
