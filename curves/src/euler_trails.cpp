// Euler trails of a graph (euler_trails.h).
#include "euler_trails.h"

#include <numeric>

namespace curvescan::detail {
namespace {

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace

std::vector<std::vector<std::size_t>> euler_trails(
    std::size_t vertex_count, const std::vector<std::pair<std::size_t, std::size_t>>& input) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  edges.reserve(input.size());
  for (const auto& e : input) {
    if (e.first != e.second) edges.push_back(e);
  }
  const std::size_t real_edges = edges.size();
  std::vector<std::size_t> parent(vertex_count);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::vector<std::size_t> degree(vertex_count, 0);
  for (const auto& [a, b] : edges) {
    ++degree[a];
    ++degree[b];
    parent[find_root(parent, a)] = find_root(parent, b);
  }
  // Pair the odd vertices of each component with virtual edges.
  std::vector<std::size_t> waiting(vertex_count, kNone);  // per component root: an unpaired odd vertex
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (degree[v] % 2 == 0) continue;
    const std::size_t root = find_root(parent, v);
    if (waiting[root] == kNone) {
      waiting[root] = v;
    } else {
      edges.emplace_back(waiting[root], v);
      waiting[root] = kNone;
    }
  }
  std::vector<std::vector<std::size_t>> adjacency(vertex_count);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    adjacency[edges[e].first].push_back(e);
    adjacency[edges[e].second].push_back(e);
  }
  auto other = [&](std::size_t e, std::size_t v) {
    return edges[e].first == v ? edges[e].second : edges[e].first;
  };
  std::vector<bool> used(edges.size(), false);
  std::vector<std::size_t> next_edge(vertex_count, 0);
  std::vector<std::vector<std::size_t>> trails;
  std::vector<std::pair<std::size_t, std::size_t>> stack;  // (vertex, edge it was reached by)
  std::vector<std::size_t> circuit;                        // edges, in the order they are popped
  for (std::size_t start = 0; start < vertex_count; ++start) {
    if (next_edge[start] == adjacency[start].size()) continue;
    // Hierholzer: walk until stuck, back up, splice.
    circuit.clear();
    stack.assign(1, {start, kNone});
    while (!stack.empty()) {
      const std::size_t v = stack.back().first;
      std::size_t& k = next_edge[v];
      while (k < adjacency[v].size() && used[adjacency[v][k]]) ++k;
      if (k < adjacency[v].size()) {
        const std::size_t e = adjacency[v][k];
        used[e] = true;
        stack.emplace_back(other(e, v), e);
      } else {
        if (stack.back().second != kNone) circuit.push_back(stack.back().second);
        stack.pop_back();
      }
    }
    if (circuit.empty()) continue;
    // Start right after a virtual edge, if any, so that cutting at them leaves whole trails.
    std::size_t first = 0;
    std::size_t vertex = start;
    for (std::size_t i = 0; i < circuit.size(); ++i) {
      if (circuit[i] >= real_edges) {
        first = i + 1;
        std::size_t v = start;
        for (std::size_t j = 0; j <= i; ++j) v = other(circuit[j], v);
        vertex = v;
        break;
      }
    }
    std::vector<std::size_t> trail{vertex};
    for (std::size_t n = 0; n < circuit.size(); ++n) {
      const std::size_t e = circuit[(first + n) % circuit.size()];
      vertex = other(e, vertex);
      if (e >= real_edges) {
        if (trail.size() >= 2) trails.push_back(std::move(trail));
        trail.assign(1, vertex);
      } else {
        trail.push_back(vertex);
      }
    }
    if (trail.size() >= 2) trails.push_back(std::move(trail));
  }
  return trails;
}

}  // namespace curvescan::detail
