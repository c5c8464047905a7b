#pragma once

// A simulated scan on disk: a scene rendered from views the arm can reach, with everything
// needed to measure a reconstruction against the truth. This is what `avc sim render` writes:
//
//   images/view_0000.png   colour images (8-bit sRGB; with noise if asked)
//   labels/view_0000.png   16-bit organ label of every pixel (0 background, 1 pot, 2 soil,
//                          3 stem, 4 petiole, 100+i leaf i)
//   depth/view_0000.tiff   32-bit float depth along the optical axis, metres, 0 = nothing
//   cameras.json           true cameras (core/camera/camera_io.h)
//   colmap/                the same cameras as a COLMAP text model
//   gt_mesh.ply            the ground-truth mesh with per-face label and material
//   cell_truth.json        the simulated cell (arm, turntable axis, hand-eye, intrinsics)
//   views.json             per view: camera name, joints, turntable angle, elevation, distance
//   scene.json             what was rendered: source, seed, triangle count, areas per organ

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/cell/cell_truth.h"
#include "sim/render/render_options.h"
#include "sim/scene/chessboard_scene.h"
#include "sim/scene/mesh_scene.h"
#include "sim/scene/plant.h"

namespace avc::sim {

struct RenderDatasetOptions {
  // The scene: a preset plant, or a mesh file placed on the turntable.
  PlantPreset preset = PlantPreset::kRosette;
  uint32_t plant_seed = 1;
  PlantOptions plant;
  std::filesystem::path mesh_file;  // non-empty: render this instead of a preset
  MeshPlacement placement;
  // Set: a calibration chessboard lying on the turntable instead of any plant.
  std::optional<ChessboardSpec> chessboard;

  // The views: `views` spread over `rings` elevations (the paper's initial set is 3 x 10),
  // turntable angles evenly spaced per ring, the camera on the arm's side of the table.
  int views = 30;
  int rings = 3;
  double min_elevation = 0.26;  // radians (15 deg)
  double max_elevation = 0.96;  // radians (55 deg)
  // Metres from the plant centre; 0 = fit the plant in view, or as near to that as the arm reaches.
  double distance = 0;

  // The cell: nominal, or perturbed from cell_seed (what a real, imperfect cell looks like).
  std::optional<uint32_t> cell_seed = 1;
  int width = 0, height = 0;  // image size; 0 = the cell camera's (1280 x 960)

  RenderOptions render;
  bool noise = false;  // exposure changes and pixel noise (seeded per view)

  std::filesystem::path output;  // created; refused if it exists and is not empty

  // Empty when usable; else a sentence naming the bad option.
  std::string Validate() const;
};

struct RenderDatasetSummary {
  int views = 0;
  size_t triangles = 0;
  double seconds_rendering = 0;
  std::vector<std::string> files;  // relative to output, in the order written
};

using ProgressCallback = std::function<void(int done, int total, const std::string& what)>;

// The scene the options describe (a preset plant or a placed mesh) and the cell they render it
// in (nominal or perturbed, image size scaled); shared with the live simulated cell.
Scene MakeScene(const RenderDatasetOptions& options);
CellTruth MakeCell(const RenderDatasetOptions& options);

// Throws std::runtime_error / std::invalid_argument naming the problem (bad options, an
// unreadable mesh, a view the arm cannot reach, an output that cannot be written).
RenderDatasetSummary RenderDataset(const RenderDatasetOptions& options,
                                   const ProgressCallback& progress = {});

}  // namespace avc::sim
