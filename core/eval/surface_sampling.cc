#include "core/eval/surface_sampling.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>

#include "core/util/keyed_random.h"

namespace avc::eval {
namespace {

// A double in [0, 1) from the top 53 bits of one draw.
double UnitDouble(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

uint64_t DeriveSeed(uint64_t seed, uint64_t stream) { return util::MixSeed(seed, stream); }

SurfaceSamples SampleSurface(const geometry::Mesh& mesh, double samples_per_m2, uint64_t seed,
                             size_t max_samples) {
  if (!(samples_per_m2 > 0) || !std::isfinite(samples_per_m2)) {
    throw std::invalid_argument(
        fmt::format("sampling density {} per m^2 must be positive and finite", samples_per_m2));
  }
  if (const std::string problem = mesh.Validate(); !problem.empty()) {
    throw std::invalid_argument("cannot sample an inconsistent mesh: " + problem);
  }
  std::vector<double> face_areas(mesh.num_faces());
  SurfaceSamples samples;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3i& face = mesh.faces[f];
    const Eigen::Vector3d a = mesh.vertices[face[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[face[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[face[2]].cast<double>();
    face_areas[f] = 0.5 * (b - a).cross(c - a).norm();
    samples.area += face_areas[f];
  }
  const double expected = samples.area * samples_per_m2;
  if (expected > static_cast<double>(max_samples)) {
    throw std::invalid_argument(fmt::format(
        "sampling {:.6g} m^2 at {:.6g} samples per m^2 would draw {:.0f} samples (limit {}); "
        "if the mesh is in millimetres scale it to metres, or lower the density",
        samples.area, samples_per_m2, expected, max_samples));
  }
  samples.samples_per_m2 = samples_per_m2;
  samples.seed = seed;
  const size_t reserve = static_cast<size_t>(expected) + mesh.num_faces() / 2 + 16;
  samples.points.reserve(reserve);
  samples.normals.reserve(reserve);
  samples.faces.reserve(reserve);

  std::mt19937_64 rng(seed);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!(face_areas[f] > 0)) continue;
    const double count = face_areas[f] * samples_per_m2;
    const double whole = std::floor(count);
    const size_t n = static_cast<size_t>(whole) + (UnitDouble(rng) < count - whole ? 1 : 0);
    if (n == 0) continue;
    const Eigen::Vector3i& face = mesh.faces[f];
    const Eigen::Vector3d a = mesh.vertices[face[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[face[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[face[2]].cast<double>();
    const Eigen::Vector3f normal = (b - a).cross(c - a).normalized().cast<float>();
    for (size_t i = 0; i < n; ++i) {
      // sqrt warps the first coordinate so the density over the triangle is uniform.
      const double s = std::sqrt(UnitDouble(rng));
      const double t = UnitDouble(rng);
      samples.points.push_back((1 - s) * a + s * (1 - t) * b + s * t * c);
      samples.normals.push_back(normal);
      samples.faces.push_back(static_cast<int32_t>(f));
    }
  }
  return samples;
}

}  // namespace avc::eval
