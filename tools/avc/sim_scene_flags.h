#pragma once

// The flags `avc sim render` and `avc sim cell` share: which plant (a preset or a mesh file), in
// which cell (nominal or perturbed), at which image size and render quality.

#include <CLI/CLI.hpp>
#include <string>

#include "sim/dataset/render_dataset.h"

namespace avc::cli {

struct SimSceneArgs {
  std::string plant = "rosette";
  uint32_t cell_seed = 1;
  bool nominal_cell = false;
  std::string background = "cloth";
  std::string chessboard;  // "COLSxROWS" inner corners; empty = a plant
  double square_m = 0.025;
  sim::RenderDatasetOptions options;  // the scene, cell and render fields are filled in
};

void AddSimSceneFlags(CLI::App& command, SimSceneArgs& args);
// Turns the parsed flags into options (preset, cell seed, background). Throws
// std::invalid_argument for an unknown preset.
void ResolveSimScene(SimSceneArgs& args);

}  // namespace avc::cli
