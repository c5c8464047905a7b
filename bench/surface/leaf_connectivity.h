#pragma once

// How many leaves of a plant a reconstruction covers in one connected piece: each
// reconstructed face belongs to the leaf of the ground-truth face nearest its centroid, and a
// leaf counts as connected when its faces form one component (faces sharing a vertex).

#include "core/geometry/mesh.h"

namespace avc::bench {

struct LeafConnectivity {
  int leaves = 0;         // leaves of the ground truth (face labels)
  int one_component = 0;  // leaves whose reconstructed faces are one connected piece
  double Fraction() const { return leaves > 0 ? static_cast<double>(one_component) / leaves : 0; }
};

// truth: the leaves' ground truth with face labels. A leaf that got no faces is not connected.
LeafConnectivity CountConnectedLeaves(const geometry::Mesh& truth, const geometry::Mesh& mesh);

}  // namespace avc::bench
