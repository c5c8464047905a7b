#pragma once

// Area-uniform random samples of a mesh surface, reproducible from a seed: the ground-truth
// samples of completeness and coverage, and the points of a reconstructed mesh.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::eval {

struct SurfaceSamples {
  std::vector<Eigen::Vector3d> points;   // on the surface, metres
  std::vector<Eigen::Vector3f> normals;  // unit normal of the sampled face (its front side)
  std::vector<int32_t> faces;            // index of the sampled face
  double area = 0;                       // sampled surface area (m^2), one-sided
  double samples_per_m2 = 0;
  uint64_t seed = 0;

  size_t size() const { return points.size(); }
};

// Draws about area * samples_per_m2 points, uniform by area: each face gets
// floor(area_f * density) samples plus one more with probability equal to the remainder
// (lower variance than drawing faces at random), at uniform barycentric positions.
// Degenerate faces get none. Same mesh, density and seed → same samples on any machine (own
// mapping from std::mt19937_64 bits, no std distributions).
// Throws std::invalid_argument when the density is not positive and finite, or when the
// expected count exceeds max_samples (a sign of a mesh in millimetres read as metres).
SurfaceSamples SampleSurface(const geometry::Mesh& mesh, double samples_per_m2, uint64_t seed,
                             size_t max_samples = 5'000'000);

// A seed for an independent random stream derived from a user seed (SplitMix64 finaliser), so
// ground-truth and reconstruction samples drawn from one user seed are not correlated.
uint64_t DeriveSeed(uint64_t seed, uint64_t stream);

}  // namespace avc::eval
