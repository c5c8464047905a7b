#pragma once

// Small labelled point sets for the clustering tests: planes, a bent sheet, a leaf on a stem,
// crossing sheets, and the measurement noise of a merged cloud.

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "core/cluster/point_set.h"
#include "core/util/ordered_draws.h"

namespace avc::cluster::testing {

// Uniform in [0, 1) from the top 53 bits (same on every standard library).
inline double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Adds count points of a w x h rectangle spanned by u, v from origin, normal u x v.
inline void AddRectangle(PointSet* set, const Eigen::Vector3f& origin, const Eigen::Vector3f& u,
                         const Eigen::Vector3f& v, float w, float h, int count, int32_t label,
                         std::mt19937_64& rng) {
  const Eigen::Vector3f normal = u.cross(v).normalized();
  for (int k = 0; k < count; ++k) {
    const float a = static_cast<float>(Uniform(rng)) * w;
    const float b = static_cast<float>(Uniform(rng)) * h;
    set->points.push_back(origin + a * u + b * v);
    set->normals.push_back(normal);
    set->labels.push_back(label);
  }
}

// Adds count points of a vertical cylinder (axis z) of the given radius, from z0 to z1.
inline void AddCylinder(PointSet* set, const Eigen::Vector3f& base, float radius, float length,
                        int count, int32_t label, std::mt19937_64& rng) {
  for (int k = 0; k < count; ++k) {
    const float angle = static_cast<float>(2.0 * std::numbers::pi * Uniform(rng));
    const float z = static_cast<float>(Uniform(rng)) * length;
    const Eigen::Vector3f normal(std::cos(angle), std::sin(angle), 0.0f);
    set->points.push_back(base + radius * normal + Eigen::Vector3f(0, 0, z));
    set->normals.push_back(normal);
    set->labels.push_back(label);
  }
}

// Adds count points of a horizontal disc (normal +z).
inline void AddDisc(PointSet* set, const Eigen::Vector3f& centre, float radius, int count,
                    int32_t label, std::mt19937_64& rng) {
  for (int k = 0; k < count; ++k) {
    const float r = radius * static_cast<float>(std::sqrt(Uniform(rng)));
    const float angle = static_cast<float>(2.0 * std::numbers::pi * Uniform(rng));
    set->points.push_back(centre + Eigen::Vector3f(r * std::cos(angle), r * std::sin(angle), 0));
    set->normals.push_back(Eigen::Vector3f::UnitZ());
    set->labels.push_back(label);
  }
}

// Standard normal (Box-Muller on two uniforms).
inline float Gaussian(std::mt19937_64& rng) {
  const double u1 = 1.0 - Uniform(rng);  // (0, 1]
  const double u2 = Uniform(rng);
  return static_cast<float>(std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2));
}

// Perturbs every point by position_sigma (m, per axis) and every normal by about normal_sigma
// (rad, per axis), as a merged multi-view stereo cloud would be.
inline void AddNoise(PointSet* set, float position_sigma, float normal_sigma,
                     std::mt19937_64& rng) {
  for (size_t i = 0; i < set->points.size(); ++i) {
    const Eigen::Vector3f dp = util::DrawVector3<Eigen::Vector3f>([&] { return Gaussian(rng); });
    const Eigen::Vector3f dn = util::DrawVector3<Eigen::Vector3f>([&] { return Gaussian(rng); });
    set->points[i] += position_sigma * dp;
    set->normals[i] = (set->normals[i] + normal_sigma * dn).normalized();
  }
}

}  // namespace avc::cluster::testing
