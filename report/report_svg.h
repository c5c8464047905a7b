#pragma once

// The scan report's static pictures, written as inline SVG: the mesh seen orthographically from
// the front, the side and the top, a horizontal bar chart and a line chart.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/mesh.h"
#include "report/mesh_render.h"

namespace avc::report {

// The mesh seen orthographically from `view` (mesh_render.h: every face drawn, depth-buffered), as
// an SVG holding the picture as an embedded PNG and the view's name: the page's fallback when
// WebGL is missing, and what a printout shows. `face_colours` holds one RGB per face.
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
