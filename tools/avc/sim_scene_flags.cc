#include "tools/avc/sim_scene_flags.h"

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
