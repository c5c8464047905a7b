#pragma once

// The mesh seen orthographically from the front, the side or the top, as a picture: every face is
// rasterised with a depth buffer (no face is dropped however small it projects) at twice the
// output size and averaged down, so thin organs and finely tessellated leaves come out solid
// and with smooth edges. The scan report's static renders (report_svg.h) embed it.

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::report {

enum class MeshView { kFront, kSide, kTop };  // looking along +y, along -x, down -z (z is up)

// "front", "side" or "top".
const char* NameOf(MeshView view);

// A size_px x size_px 8-bit BGR image on white; the bounding box of the mesh's finite vertices
// fits it with an 8-pixel margin (the same scale for all three views), and a face with a
// non-finite corner is left out. Each face is painted in its colour (`face_colours`, one RGB per
// face) shaded by how squarely it faces the viewer. Same mesh, same bytes.
cv::Mat RenderMeshView(const geometry::Mesh& mesh,
                       const std::vector<std::array<uint8_t, 3>>& face_colours, MeshView view,
                       int size_px);

}  // namespace avc::report
