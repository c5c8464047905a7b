#include "sim/scene/pot.h"

#include <array>
#include <cmath>
#include <vector>

#include "sim/scene/procedural_noise.h"

namespace avc::sim {
namespace {

struct ProfilePoint {
  float radius;
  float z;
  int segments;  // segments from the previous point
};

// The wall profile, traced from the foot up the outside, over the rim and down the inside to the
// soil, so the swept surface faces outwards outside and towards the axis inside.
constexpr std::array<ProfilePoint, 7> kProfile = {{
    {0.056f, 0.000f, 0},
    {0.0700f, 0.112f, 8},  // tapered outer wall
    {0.0755f, 0.114f, 1},  // rim band: step out
    {0.0760f, 0.130f, 2},
    {0.0745f, 0.132f, 1},  // rounded top of the rim
    {0.0700f, 0.132f, 1},
    {0.0685f, 0.118f, 2},  // inner wall down to the soil
}};
constexpr float kSoilHeight = 0.118f;
constexpr float kSoilRadius = 0.0690f;  // reaches just into the inner wall: no gap
constexpr float kSoilRoughness = 0.003f;

int ProfileSegments() {
  int total = 0;
  for (const ProfilePoint& point : kProfile) total += point.segments;
  return total;
}

void AppendPot(const MeshResolution& resolution, int32_t material, geometry::Mesh* mesh) {
  const int around = resolution.pot_around;
  const int first = static_cast<int>(mesh->vertices.size());
  // Profile samples (radius, z), each profile span split into its segments.
  std::vector<Eigen::Vector2f> samples = {{kProfile[0].radius, kProfile[0].z}};
  for (size_t p = 1; p < kProfile.size(); ++p) {
    const Eigen::Vector2f from(kProfile[p - 1].radius, kProfile[p - 1].z);
    const Eigen::Vector2f to(kProfile[p].radius, kProfile[p].z);
    for (int s = 1; s <= kProfile[p].segments; ++s) {
      samples.push_back(from + (to - from) * (static_cast<float>(s) / kProfile[p].segments));
    }
  }
  const int rings = static_cast<int>(samples.size());
  float along = 0;
  for (int k = 0; k < rings; ++k) {
    if (k > 0) along += (samples[k] - samples[k - 1]).norm();
    const float radius = samples[k].x();
    for (int j = 0; j <= around; ++j) {
      const float angle = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(around);
      mesh->vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle),
                                  samples[k].y());
      mesh->uvs.emplace_back(angle * radius, along);
    }
  }
  const int row = around + 1;
  for (int k = 0; k + 1 < rings; ++k) {
    for (int j = 0; j < around; ++j) {
      const int a = first + k * row + j;
      const int b = a + row;  // next ring up the profile
      mesh->faces.emplace_back(a, a + 1, b + 1);
      mesh->faces.emplace_back(a, b + 1, b);
    }
  }
  const size_t added = 2 * static_cast<size_t>(around) * (rings - 1);
  mesh->face_labels.insert(mesh->face_labels.end(), added, geometry::labels::kPot);
  mesh->face_materials.insert(mesh->face_materials.end(), added, material);
}

void AppendSoil(const MeshResolution& resolution, uint32_t seed, int32_t material,
                geometry::Mesh* mesh) {
  const int around = resolution.pot_around;
  const int rings = resolution.soil_rings;
  const int centre = static_cast<int>(mesh->vertices.size());
  auto height = [seed](float x, float y) {
    // Small lumps of about 1 cm.
    const float lumps = noise::ValueNoise(x / 0.01f, y / 0.01f, seed) - 0.5f;
    return kSoilHeight + kSoilRoughness * lumps;
  };
  mesh->vertices.emplace_back(0.0f, 0.0f, height(0, 0));
  mesh->uvs.emplace_back(0.0f, 0.0f);
  for (int k = 1; k <= rings; ++k) {
    const float radius = kSoilRadius * static_cast<float>(k) / static_cast<float>(rings);
    for (int j = 0; j < around; ++j) {
      const float angle = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(around);
      const float x = radius * std::cos(angle);
      const float y = radius * std::sin(angle);
      const float edge = k == rings ? 0.0f : 1.0f;  // the rim ring lies flat against the wall
      mesh->vertices.emplace_back(x, y, kSoilHeight + edge * (height(x, y) - kSoilHeight));
      mesh->uvs.emplace_back(x, y);
    }
  }
  auto ring_vertex = [&](int k, int j) { return centre + 1 + (k - 1) * around + (j % around); };
  for (int j = 0; j < around; ++j)
    mesh->faces.emplace_back(centre, ring_vertex(1, j), ring_vertex(1, j + 1));
  for (int k = 1; k < rings; ++k) {
    for (int j = 0; j < around; ++j) {
      const int a = ring_vertex(k, j);
      const int b = ring_vertex(k, j + 1);
      const int c = ring_vertex(k + 1, j + 1);
      const int d = ring_vertex(k + 1, j);
      mesh->faces.emplace_back(a, d, c);
      mesh->faces.emplace_back(a, c, b);
    }
  }
  const size_t added = static_cast<size_t>(around) * (2 * rings - 1);
  mesh->face_labels.insert(mesh->face_labels.end(), added, geometry::labels::kSoil);
  mesh->face_materials.insert(mesh->face_materials.end(), added, material);
}

}  // namespace

float SoilHeight() { return kSoilHeight; }
float PotRimRadius() { return 0.0760f; }

size_t PotTriangles(const MeshResolution& resolution) {
  const size_t around = resolution.pot_around;
  return 2 * around * ProfileSegments() + around * (2 * resolution.soil_rings - 1);
}

void AppendPotAndSoil(const MeshResolution& resolution, uint32_t seed, int32_t pot_material,
                      int32_t soil_material, geometry::Mesh* mesh) {
  AppendPot(resolution, pot_material, mesh);
  AppendSoil(resolution, seed, soil_material, mesh);
}

}  // namespace avc::sim
