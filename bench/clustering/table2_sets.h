#pragma once

// A replica of the paper's Table 2 evaluation sets (Fig. 8: six plant segments with 1 to 11+
// clusters): labelled point sets sampled from the simulated plants' per-organ labels.
//
// Each set holds kTable2SurfacePoints points sampled uniformly by area on the chosen organs (pot
// and soil never), with their face normals, position noise (sigma 0.2 mm per axis) and normal
// noise (about 3 degrees), plus 2 % outliers uniformly in the set's bounding box grown by 1 cm,
// labelled kUnassigned with random normals. Labels are the organ labels (labels::kLeafBase + i,
// labels::kStem). Petioles are left out: they all share one label although they are separate
// tubes, so they would make labels that no geometric clustering can reproduce. About 3000 points
// per set is the paper's merged density.
//
//  name              clusters  what makes it hard
//  A one-leaf        1         a cupped, ruffled broadleaf blade: must not be over-split
//  B leaf-pair       2         the two broadleaf blades with the smallest gap between them
//                              (0.6 mm apart for seed 1, 2.4 mm for seed 2, 10-15 mm for
//                              seeds 3-5: the generator decides how close they come)
//  C leaves-on-stem  3         B's pair plus the main stem, a tapered tube that is not flat
//                              and must still stay one cluster
//  D crowded-crown   7         the six highest (youngest, most crowded) broadleaf blades + stem
//  E bushy-top       8         the eight highest small bushy (chilli) blades: small, close,
//                              stacked above one another
//  F bushy-canopy    12        the twelve highest bushy blades
//
// Deterministic: the plants come from sim::GeneratePlant with seeds derived from seed, the
// sampling from one std::mt19937_64 per set with our own mapping of its bits.

#include <cstdint>
#include <vector>

#include "core/cluster/point_set.h"

namespace avc::cluster {

inline constexpr int kTable2SurfacePoints = 3000;

// The six sets A-F in order (names as in the table above).
std::vector<PointSet> Table2Sets(uint64_t seed);

// Number of distinct ground-truth labels (kUnassigned excluded) of a labelled set.
int CountClusters(const PointSet& set);

}  // namespace avc::cluster
