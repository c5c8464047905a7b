#include "core/cluster/hungarian.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace avc::cluster {
namespace {

// Rows <= cols (e-maxx formulation, 1-based with potentials u, v).
std::vector<int> SolveWide(const std::vector<std::vector<double>>& a, size_t n, size_t m) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0);
  std::vector<double> v(m + 1, 0.0);
  std::vector<size_t> p(m + 1, 0);    // row matched to column j (0 = none)
  std::vector<size_t> way(m + 1, 0);  // previous column on the augmenting path
  for (size_t i = 1; i <= n; ++i) {
    p[0] = i;
    size_t j0 = 0;
    std::vector<double> minv(m + 1, inf);
    std::vector<bool> used(m + 1, false);
    do {
      used[j0] = true;
      const size_t i0 = p[j0];
      double delta = inf;
      size_t j1 = 0;
      for (size_t j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = a[i0 - 1][j - 1] - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (size_t j = 0; j <= m; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> row_to_col(n, -1);
  for (size_t j = 1; j <= m; ++j) {
    if (p[j] != 0) row_to_col[p[j] - 1] = static_cast<int>(j - 1);
  }
  return row_to_col;
}

}  // namespace

std::vector<int> SolveAssignment(const std::vector<std::vector<double>>& cost) {
  const size_t rows = cost.size();
  if (rows == 0) return {};
  const size_t cols = cost[0].size();
  for (size_t r = 0; r < rows; ++r) {
    if (cost[r].size() != cols) {
      throw std::invalid_argument("SolveAssignment: row " + std::to_string(r) + " has " +
                                  std::to_string(cost[r].size()) + " columns, row 0 has " +
                                  std::to_string(cols));
    }
    for (double c : cost[r]) {
      if (!std::isfinite(c)) {
        throw std::invalid_argument("SolveAssignment: non-finite cost in row " + std::to_string(r));
      }
    }
  }
  if (cols == 0) return std::vector<int>(rows, -1);
  if (rows <= cols) return SolveWide(cost, rows, cols);
  // Transpose so the smaller side is the rows, then invert the matching.
  std::vector<std::vector<double>> transposed(cols, std::vector<double>(rows));
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < cols; ++c) transposed[c][r] = cost[r][c];
  }
  const std::vector<int> col_to_row = SolveWide(transposed, cols, rows);
  std::vector<int> row_to_col(rows, -1);
  for (size_t c = 0; c < cols; ++c)
    row_to_col[static_cast<size_t>(col_to_row[c])] = static_cast<int>(c);
  return row_to_col;
}

}  // namespace avc::cluster
