#include "tools/avc/sim_scene_flags.h"

#include <sstream>
#include <stdexcept>

namespace avc::cli {

void AddSimSceneFlags(CLI::App& command, SimSceneArgs& args) {
  sim::RenderDatasetOptions& o = args.options;
  command.add_option("--plant", args.plant, "preset: rosette, broadleaf, strap or bushy")
      ->capture_default_str();
  command.add_option("--seed", o.plant_seed, "plant seed (same seed, same plant)")
      ->capture_default_str();
  command.add_option("--triangles", o.plant.target_triangles, "approximate plant triangles")
      ->capture_default_str()
      ->check(CLI::Range(1000, 5'000'000));
  command.add_option("--mesh", o.mesh_file, "render this mesh (PLY, OBJ, OFF) instead of a preset")
      ->check(CLI::ExistingFile);
  command.add_option("--mesh-scale", o.placement.scale,
                     "file units to metres, e.g. 0.001 for mm (default: fit --mesh-height)");
  command.add_option("--mesh-height", o.placement.target_height, "height in metres to scale to")
      ->capture_default_str();
  command.add_flag("--y-up", o.placement.y_up, "the mesh's up axis is +y");
  command.add_option("--chessboard", args.chessboard,
                     "a calibration chessboard with COLSxROWS inner corners (e.g. 9x6) on the "
                     "turntable instead of a plant");
  command.add_option("--square", args.square_m, "chessboard square size, metres")
      ->capture_default_str();
  command.add_option("--cell-seed", args.cell_seed, "seed of the perturbed cell")
      ->capture_default_str();
  command.add_flag("--nominal-cell", args.nominal_cell,
                   "a perfect cell instead of a perturbed one");
  command.add_option("--width", o.width, "image width in pixels (default 1280)");
  command.add_option("--height", o.height, "image height in pixels (default 960)");
  command
      .add_option("--samples", o.render.samples_per_pixel_axis,
                  "anti-aliasing: N x N samples per pixel")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  command.add_option("--background", args.background, "plain or cloth")
      ->capture_default_str()
      ->check(CLI::IsMember({"plain", "cloth"}));
  command.add_flag("--noise", o.noise, "add exposure changes and pixel noise");
}

void ResolveSimScene(SimSceneArgs& args) {
  sim::RenderDatasetOptions& options = args.options;
  if (!args.chessboard.empty()) {
    sim::ChessboardSpec board;
    char x = 0;
    std::istringstream in(args.chessboard);
    if (!(in >> board.inner_cols >> x >> board.inner_rows) || x != 'x' || !in.eof()) {
      throw std::invalid_argument("--chessboard wants COLSxROWS inner corners, e.g. 9x6; got '" +
                                  args.chessboard + "'");
    }
    board.square_m = args.square_m;
    board.T_world_board =
        sim::ChessboardSpec::DefaultBoardPose(board.inner_cols, board.inner_rows, board.square_m);
    options.chessboard = board;
  }
  options.preset = sim::ParsePreset(args.plant);
  if (args.nominal_cell) {
    options.cell_seed.reset();
  } else {
    options.cell_seed = args.cell_seed;
  }
  options.render.background.kind =
      args.background == "plain" ? sim::Background::Kind::kPlain : sim::Background::Kind::kCloth;
}

}  // namespace avc::cli
