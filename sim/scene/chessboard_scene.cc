#include "sim/scene/chessboard_scene.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::sim {

Scene ChessboardScene(const ChessboardSpec& spec) {
  if (const std::string problem = spec.Validate(); !problem.empty()) {
    throw std::invalid_argument("chessboard: " + problem);
  }
  Scene scene;
  scene.name =
      fmt::format("chessboard {}x{} {} mm", spec.inner_cols, spec.inner_rows, spec.square_m * 1000);
  Material black{.name = "board black", .kind = MaterialKind::kPlain};
  black.base_rgb = Eigen::Vector3f::Constant(0.03f);
  black.variation = 0;
  Material white{.name = "board white", .kind = MaterialKind::kPlain};
  white.base_rgb = Eigen::Vector3f::Constant(0.85f);
  white.variation = 0;
  scene.materials = {black, white};

  geometry::Mesh& mesh = scene.mesh;
  const double s = spec.square_m;
  // One quad in board coordinates (x0,y0)-(x1,y1), its front on the board's -z side (up).
  const auto add_quad = [&](double x0, double y0, double x1, double y1, int material) {
    const int first = static_cast<int>(mesh.vertices.size());
    for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}) {
      mesh.vertices.push_back((spec.T_world_board * Eigen::Vector3d(x, y, 0)).cast<float>());
      mesh.uvs.emplace_back(static_cast<float>(x), static_cast<float>(y));
    }
    for (const Eigen::Vector3i& face : {Eigen::Vector3i(first, first + 1, first + 2),
                                        Eigen::Vector3i(first, first + 2, first + 3)}) {
      mesh.faces.push_back(face);
      mesh.face_labels.push_back(geometry::labels::kTarget);
      mesh.face_materials.push_back(material);
    }
  };
  // Squares: square (i, j) spans x in [(i-1)s, i s], y in [(j-1)s, j s]; (0, 0) is black.
  for (int j = 0; j <= spec.inner_rows; ++j) {
    for (int i = 0; i <= spec.inner_cols; ++i) {
      add_quad((i - 1) * s, (j - 1) * s, i * s, j * s, (i + j) % 2 == 0 ? 0 : 1);
    }
  }
  // The white margin as four strips around the squares.
  const double m = spec.margin_squares * s;
  const double x0 = -s, y0 = -s, x1 = spec.inner_cols * s, y1 = spec.inner_rows * s;
  if (m > 0) {
    add_quad(x0 - m, y0 - m, x1 + m, y0, 1);
    add_quad(x0 - m, y1, x1 + m, y1 + m, 1);
    add_quad(x0 - m, y0, x0, y1, 1);
    add_quad(x1, y0, x1 + m, y1, 1);
  }
  return scene;
}

}  // namespace avc::sim
