// SPDX-License-Identifier: GPL-3.0-or-later
// Structured brick block built in code (see brick_block.hpp).
#include "solid/brick_block.hpp"

namespace hbm::solver {

SolidGroup& make_brick_block(Model& m, const BrickBlock& b) {
  const int px = b.nx + 1, py = b.ny + 1, pz = b.nz + 1;
  m.nodes.resize(static_cast<std::size_t>(px) * py * pz);
  auto id = [&](int i, int j, int k) { return static_cast<Index>(i + px * (j + py * k)); };
  for (int k = 0; k < pz; ++k)
    for (int j = 0; j < py; ++j)
      for (int i = 0; i < px; ++i) {
        const auto n = static_cast<std::size_t>(id(i, j, k));
        m.nodes.user_id[n] = static_cast<std::int64_t>(n) + 1;
        m.nodes.x0.x[n] = m.nodes.x.x[n] = b.lx * i / b.nx;
        m.nodes.x0.y[n] = m.nodes.x.y[n] = b.ly * j / b.ny;
        m.nodes.x0.z[n] = m.nodes.x.z[n] = b.lz * k / b.nz;
      }
  Part part;
  part.id = 1;
  part.title = "block";
  m.parts.push_back(part);
  auto g = std::make_unique<SolidGroup>();
  g->keyword = "/BRICK";
  g->part = 0;
  g->nodes_per_element = 8;
  g->material = b.material;
  g->hourglass = b.hourglass;
  for (int k = 0; k < b.nz; ++k)
    for (int j = 0; j < b.ny; ++j)
      for (int i = 0; i < b.nx; ++i) {
        g->element_id.push_back(static_cast<std::int64_t>(g->element_id.size()) + 1);
        for (Index n : {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                        id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)})
          g->connectivity.push_back(n);
      }
  g->n_elements = g->element_id.size();
  g->initialize(m.nodes);
  for (std::size_t e = 0; e < g->n_elements; ++e)
    for (int a = 0; a < 8; ++a) m.nodes.mass0[static_cast<std::size_t>(g->connectivity[e * 8 + a])] += g->mass[e] / 8;
  m.parts[0].mass0 = 0;
  for (double me : g->mass) m.parts[0].mass0 += me;
  SolidGroup& ref = *g;
  m.groups.push_back(std::move(g));
  build_incidence(m);
  m.nodes.mass = m.nodes.mass0;
  m.nodes.inertia = m.nodes.inertia0;
  return ref;
}

}  // namespace hbm::solver
