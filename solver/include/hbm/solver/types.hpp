// SPDX-License-Identifier: GPL-3.0-or-later
// Basic types shared by every part of the engine: node/element indices, a 3-component
// struct of arrays, the fixed chunk size of element loops, and the deterministic
// chunked sum used for every reduction (energies, powers) so that results never depend
// on the number of OpenMP threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hbm::solver {

// Dense 0-based index of a node or element inside the frozen model (user ids live only
// in the id tables used by the build phase and the outputs).
using Index = std::int32_t;
inline constexpr Index kNoIndex = -1;

// Element loops run over fixed-size chunks. The chunk size never depends on the thread
// count, and per-chunk partial sums are added in chunk order (see ChunkedSum), which
// makes every reduction bitwise independent of the number of threads.
inline constexpr std::size_t kChunk = 128;

inline std::size_t n_chunks(std::size_t n) { return (n + kChunk - 1) / kChunk; }

// Three components as three arrays (x, y, z), the layout of every nodal vector field.
struct Vec3Soa {
  std::vector<double> x, y, z;
  void resize(std::size_t n, double value = 0.0) {
    x.assign(n, value);
    y.assign(n, value);
    z.assign(n, value);
  }
  void fill(double value) {
    for (auto* a : {&x, &y, &z})
      for (double& v : *a) v = value;
  }
  std::size_t size() const { return x.size(); }
};

// Deterministic reduction: each chunk writes its partial into its own slot (any thread),
// then total() adds the slots in chunk order on one thread.
class ChunkedSum {
 public:
  void reset(std::size_t n_slots) { part_.assign(n_slots, 0.0); }
  double& slot(std::size_t chunk) { return part_[chunk]; }
  double total() const {
    double s = 0.0;
    for (double p : part_) s += p;
    return s;
  }

 private:
  std::vector<double> part_;
};

}  // namespace hbm::solver
