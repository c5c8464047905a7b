#pragma once

// How many leaves of a plant a reconstruction covers in one connected piece. Each reconstructed
// face belongs to the leaf of the ground-truth face nearest its centroid; a leaf counts as
// connected when its faces form one component (faces sharing a vertex).
//
// Where two leaves touch, cross or lie stacked within a millimetre, a face of one leaf's surface
// can lie nearer the other leaf, and would count as a stray piece of it although no surface is
// missing. Such a face is ambiguous: its second-nearest leaf is within kAmbiguity of its nearest.
// The mesh settles it: an ambiguous face takes the leaf of the nearest unambiguous face the mesh
// joins it to (breadth first over shared edges), when that leaf is one of its candidates. A
// piece the mesh leaves apart stays apart. The count with every face given to its nearest leaf
// is kept as the strict one, and so is the count of leaves whose largest piece holds at least 95 %
// of their faces' area (settled attribution).

#include "core/geometry/mesh.h"

namespace avc::bench {

struct LeafConnectivity {
  int leaves = 0;                // leaves of the ground truth (face labels)
  int one_component = 0;         // leaves whose faces are one piece, ambiguous faces settled
  int one_component_strict = 0;  // ... with every face given to its nearest leaf
  int mostly_one = 0;            // largest piece >= 95 % of the leaf's faces' area (settled)
  double Fraction() const { return leaves > 0 ? static_cast<double>(one_component) / leaves : 0; }
};

// A face is ambiguous between leaves whose distances differ by at most this (m): five times the
// benchmark's 0.2 mm sampling noise.
constexpr double kAmbiguity = 1e-3;

// truth: the ground truth with face labels, every label a leaf unless leaf_labels_only, which
// counts only the leaf labels (geometry::labels::IsLeaf) while faces still go to the nearest
// organ of any label (a scan's mesh also covers the stem and petioles). A leaf that got no
// faces is not connected.
LeafConnectivity CountConnectedLeaves(const geometry::Mesh& truth, const geometry::Mesh& mesh,
                                      bool leaf_labels_only = false);

}  // namespace avc::bench
