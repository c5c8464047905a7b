#pragma once

// Turns one scene face (camera frame) into screen triangles: clipped against the near plane and
// the lens's guard region, split where lens distortion bends its edges by more than the allowed
// error, snapped to fixed point. Shared edges of neighbouring faces are clipped and split the same
// way (every decision depends only on the edge's two endpoints, taken in a canonical order), so
// the rasterised surface stays watertight.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "sim/render/frame_geometry.h"
#include "sim/render/lens_model.h"

namespace avc::sim {

class FaceTessellator {
 public:
  FaceTessellator(const LensModel& lens, const SampleGrid& grid, double near_clip_m,
                  double max_edge_error_px);

  // Bit k set when p is outside clip plane k (near plane, then the guard region's four sides).
  uint8_t Outcode(const Eigen::Vector3d& p) const;
  // Projects p (in front of the near plane).
  ScreenVertex MakeVertex(const Eigen::Vector3d& p) const;

  struct Outcome {
    bool clipped = false;     // cut by the near plane or the guard region
    bool subdivided = false;  // split because of distortion
  };
  // Appends the screen triangles of a face to out, tagged with shading. Vertices with outcode 0
  // must have been made by MakeVertex; for the others only p is used.
  Outcome Tessellate(const std::array<const ScreenVertex*, 3>& vertices,
                     const std::array<uint8_t, 3>& outcodes, int32_t shading,
                     std::vector<RasterTriangle>* out) const;

 private:
  // Midpoint (in the image) of the 3D edge a-b when its image bends more than allowed.
  bool SplitEdge(const ScreenVertex& a, const ScreenVertex& b, ScreenVertex* mid) const;
  void Subdivide(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int depth,
                 int32_t shading, bool* subdivided, std::vector<RasterTriangle>* out) const;
  void Emit(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int32_t shading,
            std::vector<RasterTriangle>* out) const;
  void EmitOrSubdivide(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                       int32_t shading, bool* subdivided, std::vector<RasterTriangle>* out) const;

  const LensModel& lens_;
  SampleGrid grid_;
  double max_error_px_;
  int width_, height_;
  // Clip planes f(p) >= 0 inside: near, then the four sides of the guard region.
  std::array<Eigen::Vector4d, 5> planes_;
};

}  // namespace avc::sim
