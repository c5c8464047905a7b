#pragma once

// A small Nelder–Mead minimiser for the 3-DoF patch refinement: no derivatives (NCC over
// bilinear samples is only piecewise smooth) and a handful of evaluations per step.

#include <algorithm>
#include <array>
#include <numeric>

namespace avc::mvs::patch {

template <int N>
using NmPoint = std::array<double, N>;

// Minimises cost from `start` with initial simplex steps `step`; stops after `max_iterations`
// or when the simplex's cost spread falls below `tolerance`. Returns the best point; its cost
// goes to *best_cost. Deterministic: ties keep the earlier vertex.
template <int N, class Cost>
NmPoint<N> NelderMead(const Cost& cost, const NmPoint<N>& start, const NmPoint<N>& step,
                      int max_iterations, double tolerance, double* best_cost) {
  std::array<NmPoint<N>, N + 1> x;
  std::array<double, N + 1> f;
  x[0] = start;
  f[0] = cost(x[0]);
  for (int i = 0; i < N; ++i) {
    x[i + 1] = start;
    x[i + 1][i] += step[i];
    f[i + 1] = cost(x[i + 1]);
  }
  std::array<int, N + 1> order;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return f[a] < f[b]; });
    const int best = order[0], worst = order[N], second = order[N - 1];
    if (f[worst] - f[best] < tolerance) break;
    NmPoint<N> centroid{};
    for (int k = 0; k < N; ++k) {
      for (int d = 0; d < N; ++d) centroid[d] += x[order[k]][d] / N;
    }
    auto along = [&](double t) {
      NmPoint<N> p;
      for (int d = 0; d < N; ++d) p[d] = centroid[d] + t * (x[worst][d] - centroid[d]);
      return p;
    };
    const NmPoint<N> reflected = along(-1.0);
    const double fr = cost(reflected);
    if (fr < f[best]) {
      const NmPoint<N> expanded = along(-2.0);
      const double fe = cost(expanded);
      if (fe < fr) {
        x[worst] = expanded, f[worst] = fe;
      } else {
        x[worst] = reflected, f[worst] = fr;
      }
      continue;
    }
    if (fr < f[second]) {
      x[worst] = reflected, f[worst] = fr;
      continue;
    }
    const bool outside = fr < f[worst];
    const NmPoint<N> contracted = along(outside ? -0.5 : 0.5);
    const double fc = cost(contracted);
    if (fc < (outside ? fr : f[worst])) {
      x[worst] = contracted, f[worst] = fc;
      continue;
    }
    for (int k = 1; k <= N; ++k) {  // shrink towards the best vertex
      const int v = order[k];
      for (int d = 0; d < N; ++d) x[v][d] = x[best][d] + 0.5 * (x[v][d] - x[best][d]);
      f[v] = cost(x[v]);
    }
  }
  int best = 0;
  for (int k = 1; k <= N; ++k) {
    if (f[k] < f[best]) best = k;
  }
  *best_cost = f[best];
  return x[best];
}

}  // namespace avc::mvs::patch
