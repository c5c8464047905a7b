#include "bench/mvs/ppr_bench_case.h"

#include <chrono>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "bench/mvs/plant_organs.h"
#include "core/dataset/dataset_reader.h"
#include "core/dataset/view_transforms.h"
#include "core/eval/voxel_overlap.h"
#include "core/geometry/mesh_io.h"
#include "core/ppr/plant_proxy.h"
#include "core/ppr/proxy_bounds.h"
#include "core/segmentation/fill_masks.h"

namespace avc::bench {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The same views with masks from the scan's label images (stem, petioles, leaves), i.e. perfect
// segmentation, undistorted like the images.
std::vector<dataset::View> ViewsWithTrueMasks(const std::filesystem::path& scan) {
  dataset::ViewSet set = dataset::ReadDataset(scan);
  for (dataset::View& view : set.views) {
    const auto labels_file =
        scan / "labels" / (std::filesystem::path(view.name).stem().string() + ".png");
    const cv::Mat labels = cv::imread(labels_file.string(), cv::IMREAD_UNCHANGED);
    if (labels.empty()) throw std::runtime_error("cannot read " + labels_file.string());
    view.mask = labels >= geometry::labels::kStem;
    dataset::Undistort(view);
  }
  return std::move(set.views);
}

}  // namespace

nlohmann::json RunPprCase(const PprCase& ppr_case) {
  dataset::ViewSet set = dataset::ReadDataset(ppr_case.dataset);
  for (dataset::View& view : set.views) dataset::Undistort(view);
  segmentation::FillMissingMasks(set);

  const auto bounds_start = Clock::now();
  const Eigen::AlignedBox3d box = ppr::BoundsFromViews(set.views);
  const double bounds_seconds = SecondsSince(bounds_start);

  ppr::ProxyOptions options;
  options.final_voxel_size = ppr_case.voxel_size;
  const auto carve_start = Clock::now();
  ppr::PlantProxy proxy(box, options);
  for (const dataset::View& view : set.views) proxy.AddView(view);
  for (int i = 0; i < options.resolution_increases; ++i) proxy.IncreaseResolution();
  const double carve_seconds = SecondsSince(carve_start);

  const std::vector<Eigen::Vector3f> occupied = proxy.OccupiedCentres();
  nlohmann::json result = {{"views", set.views.size()},
                           {"voxel_size_m", proxy.voxel_size()},
                           {"occupied", occupied.size()},
                           {"bounds_seconds", bounds_seconds},
                           {"carve_seconds", carve_seconds}};
  if (!set.ground_truth_mesh.empty()) {
    const geometry::Mesh truth = PlantOrgans(geometry::ReadMesh(set.ground_truth_mesh));
    const eval::VoxelOverlap overlap =
        eval::CompareWithSurface(truth, occupied, proxy.box().min(), proxy.voxel_size());
    result["iou"] = overlap.Iou();
    result["voxel_precision"] = overlap.Precision();
    result["voxel_recall"] = overlap.Recall();
    result["truth_voxels"] = overlap.truth;
  }
  if (std::filesystem::exists(ppr_case.dataset / "labels")) {
    // The best any silhouette carving can do here: the same carving from perfect masks. Its IoU
    // with the surface is the ceiling of the figure above; ours against it measures the masks.
    ppr::PlantProxy ideal(box, options);
    for (const dataset::View& view : ViewsWithTrueMasks(ppr_case.dataset)) ideal.AddView(view);
    for (int i = 0; i < options.resolution_increases; ++i) ideal.IncreaseResolution();
    const std::vector<Eigen::Vector3f> ideal_occupied = ideal.OccupiedCentres();
    result["ideal_occupied"] = ideal_occupied.size();
    result["iou_with_ideal"] =
        eval::CompareVoxelSets(ideal_occupied, occupied, proxy.box().min(), proxy.voxel_size())
            .Iou();
    if (!set.ground_truth_mesh.empty()) {
      const geometry::Mesh truth = PlantOrgans(geometry::ReadMesh(set.ground_truth_mesh));
      result["ideal_iou"] =
          eval::CompareWithSurface(truth, ideal_occupied, ideal.box().min(), ideal.voxel_size())
              .Iou();
    }
  }
  return result;
}

}  // namespace avc::bench
