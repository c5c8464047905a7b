#include "bench/render/render_bench_case.h"

#include <sys/resource.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <opencv2/core.hpp>

#include "bench/summary.h"
#include "core/geometry/mesh.h"
#include "sim/render/renderer.h"

namespace avc::bench {
namespace {

double PeakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
}

double CpuMs() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto ms = [](const timeval& t) { return 1e3 * static_cast<double>(t.tv_sec) + 1e-3 * t.tv_usec; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

double NearestRank(std::vector<double> values, double percentile) {
  std::sort(values.begin(), values.end());
  const size_t rank = static_cast<size_t>(std::ceil(percentile / 100.0 * values.size()));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

}  // namespace

camera::Intrinsics BenchIntrinsics(int width, int height) {
  camera::Intrinsics k;
  k.width = width;
  k.height = height;
  k.fx = k.fy = 1.1 * width;
  k.cx = 0.5 * (width - 1);
  k.cy = 0.5 * (height - 1);
  k.distortion = {-0.08, 0.03, 0.0, 0.0, 0.0};
  return k;
}

std::vector<camera::Camera> ViewsAround(const sim::Scene& scene, const camera::Intrinsics& k,
                                        int count) {
  Eigen::Vector3f lo, hi;
  geometry::Bounds(scene.mesh, &lo, &hi);
  const Eigen::Vector3d centre = (0.5f * (lo + hi)).cast<double>();
  const double radius = std::max(1e-3, 0.5 * static_cast<double>((hi - lo).norm()));
  const double half_fov = std::atan(0.5 * std::min(k.width / k.fx, k.height / k.fy));
  // A little closer than where the bounding sphere just fits: plants are not spheres, and a scan
  // frames the plant tightly.
  const double distance = 0.75 * radius / std::sin(half_fov);
  std::vector<camera::Camera> cameras;
  for (int i = 0; i < count; ++i) {
    const double azimuth = 2 * M_PI * i / count;
    const double elevation = (i % 2 == 0 ? 20.0 : 45.0) * M_PI / 180.0;
    const Eigen::Vector3d eye =
        centre + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                            std::cos(elevation) * std::sin(azimuth),
                                            std::sin(elevation));
    const Eigen::Vector3d z = (centre - eye).normalized();
    const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
    Eigen::Matrix3d R_world_cam;
    R_world_cam << x, z.cross(x), z;
    Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
    T_world_cam.linear() = R_world_cam;
    T_world_cam.translation() = eye;
    cameras.push_back({k, T_world_cam.inverse()});
  }
  return cameras;
}

RenderCaseResult RunRenderCase(const sim::Scene& scene, const RenderCaseSpec& spec) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<size_t>(spec.threads));
  const std::vector<camera::Camera> cameras =
      ViewsAround(scene, BenchIntrinsics(spec.width, spec.height), spec.views);
  RenderCaseResult result;
  result.spec = spec;
  result.triangles = scene.mesh.num_faces();
  // One renderer and one result for all frames, as a simulator rendering view after view would.
  sim::Renderer renderer;
  sim::RenderResult frame;
  renderer.Render(scene, cameras.front(), spec.options, &frame);  // warm-up: buffers and tables
  std::vector<double> ms, raster;
  double coverage = 0;
  const double cpu_start = CpuMs();
  for (const camera::Camera& camera : cameras) {
    const auto start = std::chrono::steady_clock::now();
    renderer.Render(scene, camera, spec.options, &frame);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
    raster.push_back(static_cast<double>(frame.stats.raster_triangles));
    coverage += static_cast<double>(cv::countNonZero(frame.labels)) / frame.labels.total();
  }
  result.cpu_ms_per_frame = (CpuMs() - cpu_start) / static_cast<double>(cameras.size());
  const Summary summary = Summarize(ms);
  result.median_ms = summary.median;
  result.max_ms = summary.max;
  result.p90_ms = NearestRank(ms, 90);
  result.raster_triangles = static_cast<size_t>(Summarize(raster).median);
  result.coverage = coverage / cameras.size();
  result.max_rss_mb = PeakRssMb();
  return result;
}

}  // namespace avc::bench
