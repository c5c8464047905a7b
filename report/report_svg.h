#pragma once

// The scan report's static pictures, written as inline SVG: the mesh seen orthographically from
// the front, the side and the top (the page's fallback when WebGL is missing, and what a printout
// shows), and a horizontal bar chart.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::report {

enum class MeshView { kFront, kSide, kTop };  // looking along +y, along -x, down -z (z is up)

// A view draws at most this many faces, the largest in projection: beyond it a page of 100k
// faces would carry tens of MB of SVG for slivers a pixel wide.
inline constexpr size_t kMaxSvgFaces = 20000;

// One <polygon> per face (faces seen edge-on are skipped, and at most kMaxSvgFaces), painted
// back to front (painter's algorithm) in its colour shaded by how squarely it faces the viewer.
// All three views share one scale, fitted to the mesh's bounding box. `face_colours` holds one
// RGB per face.
std::string MeshViewSvg(const geometry::Mesh& mesh,
                        const std::vector<std::array<uint8_t, 3>>& face_colours, MeshView view,
                        int size_px);

// Horizontal bars, one per (label, value), with the value printed as `unit` after it.
std::string BarChartSvg(const std::vector<std::pair<std::string, double>>& bars,
                        const std::string& unit);

// A line of fractions (0..1) against 1, 2, ... n, with axes, 0-100 % ticks and axis labels; a
// marked point (x, fraction) drawn as a dot when x > 0.
std::string LineChartSvg(const std::vector<double>& fractions, const std::string& x_label,
                         const std::string& y_label, std::pair<double, double> marked = {});

}  // namespace avc::report
