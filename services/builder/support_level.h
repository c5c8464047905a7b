#pragma once

// What the plant stands on, found in a coarse plant proxy when the masks take it for plant (a
// white stage, a block, a pot against a dark backdrop: colour alone cannot tell them from a pale,
// dry plant). Seen from the top down, a plant's horizontal slices of occupied voxels are small:
// stems, siliques, leaves. The support is a solid under it: its top slice holds many times more
// voxels than the plant's slices above, and it holds most of the proxy's voxels. Its top is the
// plant's base; the builder cuts the proxy there and measures height from it.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace avc::builder {

struct SupportOptions {
  bool enabled = true;
  // The support's top slice holds at least this many times the median slice above it. The
  // plant's own slices vary by 2-4x (a crown of siliques, a leaf); a stage or a block under a
  // stem is 10-100x the stem's slice.
  double min_jump = 8.0;
  // The support and everything below it hold at least this fraction of the occupied voxels, so
  // a leaf whorl above a thin stem is never taken for a support.
  double min_mass_fraction = 0.5;
  // Slices of plant needed above a support before one is looked for.
  int min_plant_slices = 4;

  // Empty when valid; else a sentence naming the bad field (SupportOptions.<field>).
  std::string Validate() const;
};

struct SupportTop {
  double z = 0;              // m, world: the top face of the support's top slice
  double jump = 0;           // that slice's voxels / the median slice above it
  double mass_fraction = 0;  // of the occupied voxels, in the support and below
};

// `occupied`: centres of a proxy's occupied voxels of edge `voxel_size` (world z up). nullopt
// when disabled or no slice meets the rule.
std::optional<SupportTop> FindSupportTop(const std::vector<Eigen::Vector3f>& occupied,
                                         double voxel_size, const SupportOptions& options = {});

std::string DescribeSupport(const SupportTop& support);

}  // namespace avc::builder
