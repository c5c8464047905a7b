#pragma once

// The data of the scan report's 3-D view, as the JSON the page's script reads: the mesh (vertex
// positions, faces, a colour per face by cluster and the vertex colours as little-endian base64),
// at most kMaxPagePoints MVS points, and each kept camera as a small frustum.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "report/report_inputs.h"

namespace avc::report {

// More points slow the page without showing more: a deterministic stride keeps at most this.
inline constexpr size_t kMaxPagePoints = 50000;

// One colour per mesh face: its cluster's (report_encode.h ClusterColour), grey without labels.
std::vector<std::array<uint8_t, 3>> FaceClusterColours(const geometry::Mesh& mesh);

// The JSON text, safe inside a <script type="application/json"> element.
std::string SceneJson(const ReportInputs& inputs);

}  // namespace avc::report
