// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-deck-bench: parse+check throughput of the deck reader on a generated starter deck
// of about one million lines (a 50x50x100 brick block and a 420x600 shell plate, every
// element valid). Prints lines, seconds and lines/s; target: under 2 s for 1e6 lines.
//   hbm-deck-bench [--lines-scale S] [--repeat N] [--file]
// --file writes the deck to a temporary file and reads it with read_deck (includes the
// file read); otherwise the text is parsed from memory with read_deck_text.
#include "hbm/deck/io.hpp"

#include <ctime>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

using namespace hbm::deck;

namespace {

// CPU time of this process: under a loaded machine the wall time also counts other jobs.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void put_int(std::string& s, long long v) {
  char buf[16];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  const std::size_t n = static_cast<std::size_t>(r.ptr - buf);
  s.append(10 - n, ' ');
  s.append(buf, n);
}

void put_real(std::string& s, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  const std::size_t n = static_cast<std::size_t>(r.ptr - buf);
  s.append(20 - n, ' ');
  s.append(buf, n);
}

struct Generated {
  std::string text;
  std::size_t lines = 0;
};

Generated generate(double scale) {
  Generated g;
  std::string& s = g.text;
  const int bx = static_cast<int>(50 * scale), by = 50, bz = 100;       // brick cells
  const int px = static_cast<int>(420 * scale), py = 600;               // shell cells
  s.reserve(static_cast<std::size_t>(1.1e6 * scale * 80));
  s += "#RADIOSS STARTER\n/BEGIN\nbench\n      2024         0\n"
       "                  kg                  mm                  ms\n"
       "                  kg                  mm                  ms\n";
  g.lines += 6;
  s += "/NODE\n";
  ++g.lines;
  auto bnode = [&](int i, int j, int k) { return 1 + i + (bx + 1) * (j + (by + 1) * k); };
  const long long plate0 = 1 + static_cast<long long>(bx + 1) * (by + 1) * (bz + 1);
  auto pnode = [&](int i, int j) { return plate0 + i + static_cast<long long>(px + 1) * j; };
  for (int k = 0; k <= bz; ++k)
    for (int j = 0; j <= by; ++j)
      for (int i = 0; i <= bx; ++i) {
        put_int(s, bnode(i, j, k));
        put_real(s, 2.0 * i);
        put_real(s, 2.0 * j);
        put_real(s, 2.0 * k);
        s += '\n';
        ++g.lines;
      }
  for (int j = 0; j <= py; ++j)
    for (int i = 0; i <= px; ++i) {
      put_int(s, pnode(i, j));
      put_real(s, 1.5 * i);
      put_real(s, 1.5 * j);
      put_real(s, -10.0);
      s += '\n';
      ++g.lines;
    }
  s += "/BRICK/1\n";
  ++g.lines;
  long long eid = 1;
  for (int k = 0; k < bz; ++k)
    for (int j = 0; j < by; ++j)
      for (int i = 0; i < bx; ++i) {
        put_int(s, eid++);
        put_int(s, bnode(i, j, k));
        put_int(s, bnode(i + 1, j, k));
        put_int(s, bnode(i + 1, j + 1, k));
        put_int(s, bnode(i, j + 1, k));
        put_int(s, bnode(i, j, k + 1));
        put_int(s, bnode(i + 1, j, k + 1));
        put_int(s, bnode(i + 1, j + 1, k + 1));
        put_int(s, bnode(i, j + 1, k + 1));
        s += '\n';
        ++g.lines;
      }
  s += "/SHELL/2\n";
  ++g.lines;
  for (int j = 0; j < py; ++j)
    for (int i = 0; i < px; ++i) {
      put_int(s, eid++);
      put_int(s, pnode(i, j));
      put_int(s, pnode(i + 1, j));
      put_int(s, pnode(i + 1, j + 1));
      put_int(s, pnode(i, j + 1));
      s += '\n';
      ++g.lines;
    }
  s += "/PART/1\nblock\n         1         1\n/PART/2\nplate\n         2         1\n"
       "/PROP/TYPE14/1\nsolid\n\n/PROP/TYPE1/2\nshell\n\n\n         5                   1.\n"
       "/MAT/LAW1/1\nsteel\n              7.8E-6\n                210.                 0.3\n/END\n";
  g.lines += 19;
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  double scale = 1.0;
  int repeat = 3;
  bool use_file = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--lines-scale" && i + 1 < argc) scale = std::atof(argv[++i]);
    else if (a == "--repeat" && i + 1 < argc) repeat = std::atoi(argv[++i]);
    else if (a == "--file") use_file = true;
    else {
      std::cerr << "usage: hbm-deck-bench [--lines-scale S] [--repeat N] [--file]\n";
      return 2;
    }
  }
  if (!(scale > 0) || repeat < 1) return 2;
  auto t0 = std::chrono::steady_clock::now();
  const Generated g = generate(scale);
  auto t1 = std::chrono::steady_clock::now();
  std::printf("generated deck: %zu lines, %.1f MB in %.3f s\n", g.lines, g.text.size() / 1e6,
              std::chrono::duration<double>(t1 - t0).count());
  std::filesystem::path file;
  if (use_file) {
    file = std::filesystem::temp_directory_path() / "hbm_deck_bench_0000.rad";
    std::ofstream(file, std::ios::binary) << g.text;
  }
  double best = 1e30, best_cpu = 1e30;
  for (int r = 0; r < repeat; ++r) {
    const double ca = cpu_seconds();
    auto a = std::chrono::steady_clock::now();
    const ReadResult res = use_file ? read_deck(file, Section::Starter)
                                    : read_deck_text(g.text, "bench_0000.rad", Section::Starter);
    auto b = std::chrono::steady_clock::now();
    const double cpu = cpu_seconds() - ca;
    const double sec = std::chrono::duration<double>(b - a).count();
    if (!res.ok()) {
      print_diagnostics(std::cerr, res);
      return 1;
    }
    std::size_t rows = 0;
    for (const Card& c : res.deck.cards) rows += c.n_rows();
    std::printf("run %d: parse+check %.3f s wall, %.3f s CPU, %.2f M lines/s (%zu cards, %zu rows, 0 errors)\n",
                r + 1, sec, cpu, g.lines / sec / 1e6, res.deck.cards.size(), rows);
    best = std::min(best, sec);
    best_cpu = std::min(best_cpu, cpu);
  }
  std::printf("best: %.3f s wall (%.3f s CPU) for %zu lines = %.2f M lines/s (%s; single thread; "
              "target < 2 s per 1e6 lines)\n",
              best, best_cpu, g.lines, g.lines / best / 1e6, use_file ? "from file" : "from memory");
  if (use_file) std::filesystem::remove(file);
  return 0;
}
