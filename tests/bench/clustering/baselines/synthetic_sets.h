#pragma once

// Small labelled point sets for the clustering tests, generated from a seed.

#include <cstdint>

#include "core/cluster/point_set.h"

namespace avc::cluster::testing {

// `clusters` round blobs of `points_each` points (radius 1 cm) on a line, centres 10 cm apart;
// normals point away from each blob's centre. Labels 0..clusters-1.
PointSet Blobs(int clusters, int points_each, uint32_t seed);

// Three 6 cm square patches facing x, y and z, 10 cm apart, jittered 0.2 mm along their normal;
// normals exact. Labels 0..2.
PointSet OrthogonalPatches(int points_each, uint32_t seed);

// Two concentric circles in the xy plane (radius 5 and 15 cm, 1 mm noise): separable by
// connectivity but not by k-means. Labels 0 (inner), 1 (outer).
PointSet ConcentricRings(int points_each, uint32_t seed);

// Fraction of points whose cluster's majority label equals their own (kUnassigned points in the
// assignment count as wrong).
double Purity(const Assignment& assignment, const std::vector<int32_t>& labels);

// Number of distinct cluster ids other than kUnassigned.
int ClusterCount(const Assignment& assignment);

}  // namespace avc::cluster::testing
