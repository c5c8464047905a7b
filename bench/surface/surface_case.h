#pragma once

// One plant of `avc bench surface`: ~3000 labelled leaf points sampled on a simulated plant
// (as tests/core/surface/plant_surface_test.cc does), surfaced by ours (with one cluster per leaf
// and with the paper's Algorithm 2 clusters) and by every baseline on the same points, each
// scored against the leaves' one-sided ground truth.

#include <cstdint>
#include <string>
#include <vector>

#include "sim/scene/plant.h"

namespace avc::bench {

struct SurfaceCaseOptions {
  int points = 3000;
  double noise = 0.0002;  // m per axis, as the clustering sets (paper Table 2)
  uint32_t seed = 1;
  int repeats = 3;  // timed runs per method (median reported)
};

struct SurfaceMethodResult {
  std::string method;
  bool ok = false;
  std::string error;  // when not ok
  double area_ratio = 0;
  double rmse = 0;  // m, mesh area samples to the ground truth
  double mean = 0;  // m
  double connected_fraction = 0;
  int leaves = 0;
  int connected_leaves = 0;         // leaf_connectivity.h: attribution settled on the mesh
  int connected_leaves_strict = 0;  // ... every face given to its nearest leaf
  double height_ratio = 0;          // the height trait / the leaves' height, both above the soil
  size_t faces = 0;
  double seconds = 0;          // median over the repeats (meshing only)
  double cluster_seconds = 0;  // Algorithm 2 clustering, when the method uses it
};

struct SurfaceCaseResult {
  std::string preset;
  size_t points = 0;
  double spacing = 0;  // m, measured (median nearest-neighbour distance)
  double truth_area = 0;
  std::vector<SurfaceMethodResult> methods;
};

SurfaceCaseResult RunSurfaceCase(sim::PlantPreset preset, const SurfaceCaseOptions& options);

}  // namespace avc::bench
