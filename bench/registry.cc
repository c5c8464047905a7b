#include "bench/registry.h"

#include <cstdlib>

#include "bench/auth/auth_bench.h"
#include "bench/bus/bus_bench.h"
#include "bench/calibration/calibration_bench.h"
#include "bench/chaos/chaos_bench.h"
#include "bench/clustering/clustering_bench.h"
#include "bench/devices/devices_bench.h"
#include "bench/e2e/e2e_bench.h"
#include "bench/merge/merge_bench.h"
#include "bench/mvs/mvs_bench.h"
#include "bench/nbv/nbv_bench.h"
#include "bench/real/real_bench.h"
#include "bench/render/render_bench.h"
#include "bench/surface/surface_bench.h"

namespace avc::bench {

const std::vector<Benchmark>& AllBenchmarks() {
  static const std::vector<Benchmark> benchmarks = {
      {"auth",
       "signed motion commands: the cost of signing and checking, and a live turntable driver "
       "under unsigned, forged, altered, misdirected, wrong-cell, stale and replayed commands",
       RunAuthBenchmark},
      {"bus",
       "5 MB image products between two processes at 10 Hz and in a burst, with the "
       "recommended and the default receive buffer: delivered/sent, retransmissions, latency",
       RunBusBenchmark},
      {"render",
       "CPU renderer of the simulated cell: 1280x960 frame time on views around each plant "
       "preset and a 100k-triangle plant, 1/2x2/3x3 samples, 1 vs 2 threads, 1x/4x/16x pixels, "
       "peak memory",
       RunRenderBenchmark},
      {"devices",
       "time per captured view in the simulated cell (move, rotate, capture, transfer) with "
       "every driver a separate process on the real protocols, at real time and a faster clock",
       RunDevicesBenchmark},
      {"calibration",
       "hand-eye (closed form, Ceres, OpenCV SHAH) and turntable axis (paper, closed form, Ceres) "
       "Monte-Carlo, and the calibration end to end in the simulated cell",
       RunCalibrationBenchmark},
      {"chaos",
       "seeded crashes during simulated scans: a SIGKILL of the simulator, a driver, the recorder "
       "or avc scan at a random moment, then restart or resume; and cells scanning at once on one "
       "network: every image once, the undisturbed scan's images and mesh byte for byte",
       RunChaosBenchmark},
      {"clustering",
       "the paper's Table 2 replica: Algorithm 2 against k-means, iPDDP, dense and sparse "
       "spectral, PCL region growing on six labelled plant point sets",
       RunClusteringBenchmark},
      {"e2e",
       "avc demo end to end on simulated plants (calibration, active vision, reconstruction), "
       "against the 3x10 orbit alone: wall time, images, the mesh's leaves against the truth",
       RunE2eBenchmark},
      {"merge",
       "model merging (paper §3.1) into the plant proxy's voxels with 5 % injected outliers on "
       "simulated scans: points before and after, RMSE to the ground truth raw and merged",
       RunMergeBenchmark},
      {"mvs",
       "the builder's patch MVS against PMVS2's published run and a plane-sweep ZNCC comparator "
       "on the Middlebury dinoSparseRing and on simulated plants (30 views, 1280x960): points per "
       "image, inside-silhouette fraction, precision/recall, wall time, peak memory",
       RunMvsBenchmark},
      {"nbv",
       "the planner's active vision (Algorithm 1) against one and two static cameras, random "
       "views, the 3x10 orbit and an information-gain planner in the simulated cell: ground-truth "
       "coverage against images",
       RunNbvBenchmark},
      {"real",
       "avc reconstruct on a real scan (the shared ROMI arabidopsis) against the scanner's own "
       "mesh: MVS points and mesh precision/recall, area, pieces, masks per view, height and "
       "width, wall time and peak memory at 18, 36 and 72 views",
       RunRealBenchmark},
      {"surface",
       "the surfacer (Algorithm 3) against trimmed Poisson, greedy projection, advancing front "
       "and Pound-style patches on ~3000 leaf points of each plant preset: area ratio, RMSE, "
       "leaves in one piece, time",
       RunSurfaceBenchmark},
  };
  return benchmarks;
}

std::optional<int> ParseBenchmarkArguments(CLI::App& app, const std::vector<std::string>& args) {
  try {
    // CLI11 takes a vector of arguments last-first.
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return std::nullopt;
}

const Benchmark* FindBenchmark(const std::string& name) {
  for (const Benchmark& benchmark : AllBenchmarks()) {
    if (benchmark.name == name) return &benchmark;
  }
  return nullptr;
}

std::filesystem::path SharedDataDir() {
  if (const char* dir = std::getenv("AVC_SHARED_DATA"); dir != nullptr && *dir != '\0') return dir;
  return std::filesystem::path("..") / "shared" / "data";
}

}  // namespace avc::bench
