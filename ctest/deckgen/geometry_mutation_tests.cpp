// SPDX-License-Identifier: GPL-3.0-or-later
// Mutation robustness of hbm-deckgen (issue 6, "Bad input"): one geometry source of a copy
// of geometry/ is damaged by one to three seeded text mutations (a field replaced by junk
// such as "nan", "1e308", "abc" or nothing, a field or a character dropped, junk inserted,
// a line dropped or repeated, the file cut short, a number scaled by 0, -1, 10, 0.01 or
// 1000), and hbm-deckgen runs on it. Every run must write the model (0), stop on bad
// input (1) or on a failed check (2): never a crash, an abort or a hang. A stopped run
// names a file of the damaged geometry folder and leaves its output folder empty (outputs
// appear complete or not at all). A throw-away version of this test (about 5,000 runs) found a
// missing section row stopping with a bare "map::at".
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

const fs::path kGeometry = fs::path(HBM_SOURCE_DIR) / "geometry";

std::string read_text(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  std::string line;
  std::istringstream in(s);
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

// One damaged copy of a source file; `what` describes the mutations for the failure message.
struct Mutator {
  std::mt19937 rng;
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }

  std::string junk() {
    static const char* k[] = {"nan", "inf", "-inf", "1e308", "-1e308", "0", "-0", "1e-320", "abc", "", " ", "\"",
                              ",", "1,2", "999999999999999999999", "-1", "3.4.5", "0x10", "+", "1e", "\t", "<", "/>"};
    return k[pick(std::size(k))];
  }

  void mutate(std::vector<std::string>& lines, bool csv, std::string& what) {
    if (lines.empty()) lines.emplace_back();
    const std::size_t i = pick(lines.size());
    std::string& l = lines[i];
    const int kind = static_cast<int>(pick(8));
    what += " [line " + std::to_string(i + 1) + " kind " + std::to_string(kind) + "]";
    static const std::regex number(R"(-?\d+\.\d+)");
    switch (kind) {
      case 0:  // a field (CSV) or a number (URDF) replaced by junk
        if (csv) {
          std::vector<std::string> f;
          std::stringstream ss(l);
          std::string c;
          while (std::getline(ss, c, ',')) f.push_back(c);
          if (f.empty()) break;
          f[pick(f.size())] = junk();
          l.clear();
          for (std::size_t k = 0; k < f.size(); ++k) l += (k ? "," : "") + f[k];
        } else {
          std::smatch m;
          if (std::regex_search(l, m, number)) l = m.prefix().str() + junk() + m.suffix().str();
        }
        break;
      case 1: lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i)); break;
      case 2: lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(i), l); break;
      case 3:
        if (!l.empty()) l.erase(pick(l.size()), 1);
        break;
      case 4:
        l.insert(l.empty() ? 0 : pick(l.size()), junk());
        break;
      case 5: lines.resize(i); break;
      case 6:
        if (csv && !l.empty()) {
          const auto commas = static_cast<std::size_t>(std::count(l.begin(), l.end(), ','));
          std::size_t at = 0, k = pick(commas + 1);
          for (std::size_t n = 0; n < k; ++n) at = l.find(',', at) + 1;
          const std::size_t end = l.find(',', at);
          l.erase(at, end == std::string::npos ? std::string::npos : end - at + 1);
        }
        break;
      default: {  // a number scaled
        std::smatch m;
        if (std::regex_search(l, m, number)) {
          static const double f[] = {0, -1, 10, 0.01, 1000};
          std::ostringstream v;
          v << std::stod(m.str()) * f[pick(std::size(f))];
          l = m.prefix().str() + v.str() + m.suffix().str();
        }
      }
    }
  }
};

}  // namespace

TEST(GeometryMutation, EveryDamagedSourceEndsCleanly) {
  std::vector<fs::path> sources;
  for (const auto& e : fs::directory_iterator(kGeometry))
    if (e.path().extension() == ".csv" || e.path().extension() == ".urdf") sources.push_back(e.path().filename());
  std::sort(sources.begin(), sources.end());
  ASSERT_GE(sources.size(), 10u);

  const fs::path work = fs::temp_directory_path() / "hbm_deckgen_mutation";
  const fs::path geo = work / "geometry", out = work / "out", log = work / "console.log";
  Mutator mut{std::mt19937(20261125)};
  constexpr int kRuns = 150;
  int written = 0, bad_input = 0, failed_check = 0;
  for (int run = 0; run < kRuns; ++run) {
    fs::remove_all(work);
    fs::create_directories(work);
    fs::copy(kGeometry, geo, fs::copy_options::recursive);
    const fs::path file = sources[mut.pick(sources.size())];
    const bool csv = file.extension() == ".csv";
    std::vector<std::string> lines = split_lines(read_text(geo / file));
    std::string what = file.string();
    const std::size_t n = 1 + mut.pick(3);
    for (std::size_t k = 0; k < n; ++k) mut.mutate(lines, csv, what);
    {
      std::ofstream o(geo / file, std::ios::binary | std::ios::trunc);
      for (std::size_t k = 0; k < lines.size(); ++k) o << lines[k] << (k + 1 < lines.size() ? "\n" : "");
    }
    // A hang is a failure: hbm-deckgen takes under a second on the committed sources (150 runs: ~20 s).
    const std::string cmd = "timeout 60 " + std::string(HBM_DECKGEN_EXE) + " -g " + geo.string() + " -o " + out.string() +
                            " > " + log.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "run " << run << " (" << what << "): killed by a signal";
    const int rc = WEXITSTATUS(status);
    const std::string console = read_text(log);
    ASSERT_TRUE(rc == 0 || rc == 1 || rc == 2) << "run " << run << " (" << what << "): exit " << rc << "\n" << console;
    if (rc == 0) {
      ++written;
      continue;
    }
    (rc == 1 ? bad_input : failed_check)++;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "run " << run << " (" << what << "): exit " << rc << " left files";
    if (rc == 1) {  // bad input names a source of the damaged folder (file:line where a row is at fault)
      EXPECT_NE(console.find(geo.string() + "/"), std::string::npos) << "run " << run << " (" << what << "):\n" << console;
    }
  }
  // The mutations reach the readers, the mesher and the checks alike.
  EXPECT_GT(bad_input, kRuns / 4);
  EXPECT_GT(written + failed_check, 0);
  std::cout << "GeometryMutation: " << kRuns << " runs: " << written << " written, " << bad_input << " bad input, "
            << failed_check << " failed checks\n";
  fs::remove_all(work);
}
