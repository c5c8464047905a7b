#include "core/cluster/fiedler_vector.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>
#include <vector>

namespace avc::cluster {
namespace {

SparseGraph FromEdges(size_t vertices, const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
  SparseGraph graph;
  graph.offset.assign(vertices + 1, 0);
  for (const auto& [a, b] : edges) {
    ++graph.offset[a + 1];
    ++graph.offset[b + 1];
  }
  for (size_t v = 0; v < vertices; ++v) graph.offset[v + 1] += graph.offset[v];
  graph.column.resize(graph.offset.back());
  graph.weight.assign(graph.offset.back(), 1.0f);
  std::vector<uint32_t> fill(graph.offset.begin(), graph.offset.end() - 1);
  for (const auto& [a, b] : edges) {
    graph.column[fill[a]++] = b;
    graph.column[fill[b]++] = a;
  }
  return graph;
}

TEST(FiedlerVector, SeparatesTwoCliquesJoinedByOneEdge) {
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  for (uint32_t a = 0; a < 20; ++a) {
    for (uint32_t b = a + 1; b < 20; ++b) {
      if ((a < 10) == (b < 10)) edges.emplace_back(a, b);
    }
  }
  edges.emplace_back(9, 10);
  const SparseGraph graph = FromEdges(20, edges);
  std::vector<double> start(20);
  for (size_t v = 0; v < 20; ++v) start[v] = static_cast<double>(v % 3);  // no hint of the halves
  const std::vector<double> fiedler = FiedlerVector(graph, start, 15);
  for (size_t v = 1; v < 20; ++v) {
    EXPECT_EQ(fiedler[v] < 0, (v < 10) == (fiedler[0] < 0)) << "vertex " << v;
  }
}

TEST(FiedlerVector, IsMonotonicAlongAPath) {
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  for (uint32_t v = 0; v + 1 < 30; ++v) edges.emplace_back(v, v + 1);
  std::vector<double> start(30, 0.0);
  start[3] = 1.0;  // far from the answer
  const std::vector<double> fiedler = FiedlerVector(FromEdges(30, edges), start, 29);
  for (size_t v = 0; v + 1 < 30; ++v) EXPECT_LT(fiedler[v], fiedler[v + 1]) << "vertex " << v;
}

TEST(FiedlerVector, RejectsBadInput) {
  const SparseGraph graph = FromEdges(4, {{0, 1}, {1, 2}});  // vertex 3 isolated
  EXPECT_THROW(FiedlerVector(graph, {0, 1, 2, 3}, 3), std::invalid_argument);
  const SparseGraph path = FromEdges(4, {{0, 1}, {1, 2}, {2, 3}});
  EXPECT_THROW(FiedlerVector(path, {0, 1}, 3), std::invalid_argument);
}

}  // namespace
}  // namespace avc::cluster
