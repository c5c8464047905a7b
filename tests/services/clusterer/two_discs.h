#pragma once

// A tiny plant for the clusterer tests: two horizontal discs (leaves) 4 cm apart, sampled densely
// as MVS points, a few outliers around them, and a plant proxy whose occupied voxels are the
// voxels the disc points fall in, as an OctoMap .bt.

#include <octomap/OcTree.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "core/mvs/mvs_points.h"

namespace avc::clusterer::testing {

inline constexpr double kVoxel = 0.002;
inline constexpr int kOutliers = 100;

struct TwoDiscs {
  mvs::MvsPoints points;
  std::string proxy_bt;
};

inline TwoDiscs MakeTwoDiscs(int points_per_disc = 3000) {
  std::mt19937_64 rng(7);
  const auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  TwoDiscs scene;
  octomap::OcTree tree(kVoxel);
  const auto add = [&](const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    scene.points.cloud.positions.push_back(p);
    scene.points.cloud.normals.push_back(n);
    scene.points.cloud.colors.emplace_back(40, 160, 40);
    scene.points.confidence.push_back(0.9f);
    scene.points.views.push_back({0, 1, 2});
  };
  for (const float z : {0.05f, 0.09f}) {
    for (int k = 0; k < points_per_disc; ++k) {
      const double r = 0.02 * std::sqrt(uniform());
      const double angle = 2 * std::numbers::pi * uniform();
      const Eigen::Vector3f p(static_cast<float>(r * std::cos(angle)),
                              static_cast<float>(r * std::sin(angle)), z);
      add(p, Eigen::Vector3f::UnitZ());
      tree.updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
    }
  }
  // Outliers in the empty space beside the discs: no voxel there is occupied.
  for (int k = 0; k < kOutliers; ++k) {
    add(Eigen::Vector3f(0.03f + 0.02f * static_cast<float>(uniform()),
                        -0.02f + 0.04f * static_cast<float>(uniform()),
                        0.04f + 0.06f * static_cast<float>(uniform())),
        Eigen::Vector3f::UnitX());
  }
  std::ostringstream bytes;
  tree.writeBinaryConst(bytes);
  scene.proxy_bt = bytes.str();
  return scene;
}

}  // namespace avc::clusterer::testing
