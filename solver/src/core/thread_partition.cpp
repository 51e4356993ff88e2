// SPDX-License-Identifier: GPL-3.0-or-later
// ThreadPartition::build: node ranges and chunk owners (see thread_partition.hpp).
// The generated body model numbers its nodes and elements region by region, so node
// index order is close to a spatial order: with one cut, about 2 % of the element-node
// references of the hub model cross from one thread's range into the other's.
#include "hbm/solver/thread_partition.hpp"

#include "hbm/solver/model.hpp"

#include <algorithm>

namespace hbm::solver {

namespace {

// A piece of element work that one thread runs: a force chunk of a shared group, or a
// whole group that runs on one thread.
struct WorkPiece {
  std::size_t group = 0;
  std::size_t chunk = 0;     // unused for a whole group
  bool whole = false;
  std::size_t position = 0;  // median node index of its elements
  double cost = 0.0;         // elements x relative cost
};

// Median node index of the given elements' nodes (0 for none).
std::size_t median_node(const ElementGroup& g, std::span<const Index> elements, std::vector<Index>& scratch) {
  scratch.clear();
  const std::size_t npe = g.nodes_per_element;
  for (const Index e : elements)
    for (std::size_t k = 0; k < npe; ++k) scratch.push_back(g.connectivity[static_cast<std::size_t>(e) * npe + k]);
  if (scratch.empty()) return 0;
  auto mid = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
  std::nth_element(scratch.begin(), mid, scratch.end());
  return static_cast<std::size_t>(std::max<Index>(*mid, 0));
}

}  // namespace

void ThreadPartition::build(Model& m, int n_threads, std::span<const std::uint8_t> run_whole,
                            std::span<const double> group_seconds) {
  const auto T = static_cast<std::size_t>(std::clamp(n_threads, 1, 255));  // owners are bytes
  const std::size_t nn = m.nodes.n_nodes;
  std::vector<WorkPiece> pieces;
  std::vector<Index> elements, chunk_elements, scratch;
  for (std::size_t g = 0; g < m.groups.size(); ++g) {
    const ElementGroup& grp = *m.groups[g];
    if (grp.all_deactivated()) continue;
    const std::size_t nch = grp.n_force_chunks();
    double per_element = grp.relative_element_cost();
    if (group_seconds.size() == m.groups.size()) {
      std::size_t computed = 0;
      for (std::size_t ch = 0; ch < nch; ++ch) {
        grp.force_chunk_elements(ch, chunk_elements);
        computed += chunk_elements.size();
      }
      per_element = computed > 0 ? group_seconds[g] / static_cast<double>(computed) : 0.0;
    }
    const bool whole = g < run_whole.size() && run_whole[g] != 0;
    elements.clear();
    for (std::size_t ch = 0; ch < nch; ++ch) {
      grp.force_chunk_elements(ch, chunk_elements);
      if (whole) {
        elements.insert(elements.end(), chunk_elements.begin(), chunk_elements.end());
      } else {
        pieces.push_back({g, ch, false, median_node(grp, chunk_elements, scratch),
                          per_element * static_cast<double>(chunk_elements.size())});
      }
    }
    if (whole)
      pieces.push_back({g, 0, true, median_node(grp, elements, scratch),
                        per_element * static_cast<double>(elements.size())});
  }
  std::stable_sort(pieces.begin(), pieces.end(),
                   [](const WorkPiece& a, const WorkPiece& b) { return a.position < b.position; });
  std::vector<double> before(pieces.size() + 1, 0.0);  // work of pieces 0 .. i-1
  for (std::size_t i = 0; i < pieces.size(); ++i) before[i + 1] = before[i] + pieces[i].cost;
  const double total = before.back();
  // Cut k between the two pieces where the work before it comes closest to k / T of the
  // total, at a node chunk boundary between their positions where there is one (the
  // chunked nodal sums keep their chunks whole), else at the nearest boundary.
  node_begin.assign(T + 1, nn);
  node_begin[0] = 0;
  for (std::size_t k = 1; k < T; ++k) {
    const double target = total * static_cast<double>(k) / static_cast<double>(T);
    auto i = static_cast<std::size_t>(std::lower_bound(before.begin(), before.end(), target) - before.begin());
    if (i > 0 && target - before[i - 1] < before[i] - target) --i;
    std::size_t cut = nn;
    if (i < pieces.size()) {
      const std::size_t hi = pieces[i].position;
      cut = hi / kChunk * kChunk;
      if (i > 0 && cut <= pieces[i - 1].position) cut = std::min(nn, (hi + kChunk / 2) / kChunk * kChunk);
      if (i == 0) cut = 0;
    }
    node_begin[k] = std::max(node_begin[k - 1], std::min(cut, nn));
  }
  auto owner_of = [&](std::size_t position) {
    const auto it = std::upper_bound(node_begin.begin(), node_begin.end() - 1, position);
    const auto t = static_cast<std::size_t>(it - node_begin.begin()) - 1;
    return static_cast<std::uint8_t>(std::min(t, T - 1));
  };
  work_share.assign(T, 0.0);
  group_thread.assign(m.groups.size(), 0);
  for (auto& gp : m.groups) gp->chunk_thread.assign(gp->all_deactivated() ? 0 : gp->n_force_chunks(), 0);
  for (const WorkPiece& p : pieces) {
    const std::uint8_t t = owner_of(p.position);
    work_share[t] += total > 0.0 ? p.cost / total : 0.0;
    ElementGroup& grp = *m.groups[p.group];
    if (p.whole) {
      group_thread[p.group] = t;
      std::fill(grp.chunk_thread.begin(), grp.chunk_thread.end(), t);
    } else {
      grp.chunk_thread[p.chunk] = t;
    }
  }
  threads = n_threads;
  measured = group_seconds.size() == m.groups.size();
  if (!measured) shared = total >= kMinSharedWork;  // measured: keep the first decision
}

}  // namespace hbm::solver
