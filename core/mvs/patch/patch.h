#pragma once

// A PMVS patch: a small oriented square of surface with the images that see it.

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace avc::mvs::patch {

struct Patch {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // world, metres
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, towards the reference camera
  uint32_t reference = 0;                             // R(p)
  std::vector<uint32_t> visible;                      // V*(p): sorted, the reference included
  float score = 0;  // mean NCC with the reference over V*(p) \ R(p)
};

// Every patch made so far, by id (commit order); filtered ones stay with alive[id] == 0.
struct PatchSet {
  std::vector<Patch> patches;
  std::vector<uint8_t> alive;

  uint32_t Add(Patch patch) {
    patches.push_back(std::move(patch));
    alive.push_back(1);
    return static_cast<uint32_t>(patches.size() - 1);
  }
  std::vector<uint32_t> AliveIds() const {
    std::vector<uint32_t> ids;
    for (uint32_t id = 0; id < alive.size(); ++id) {
      if (alive[id]) ids.push_back(id);
    }
    return ids;
  }
};

}  // namespace avc::mvs::patch
