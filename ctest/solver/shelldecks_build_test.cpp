// SPDX-License-Identifier: GPL-3.0-or-later
// Unit tests of the shell builder (build_shell_groups): decks read from text, built with
// build_model. A valid deck gives one group per (keyword, part) with the thickness rule
// element > part > property, lumped mass rho t A and rotational DOFs on shell nodes;
// unsupported or inconsistent input is refused with a message naming file:line, the
// keyword and the field.
#include "hbm/deck/io.hpp"
#include "hbm/solver/build_context.hpp"
#include "shells/shell_element_group.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>

using namespace hbm::solver;

namespace {

std::string i10(long v) {
  std::string s = std::to_string(v);
  return std::string(10 - s.size(), ' ') + s;
}
std::string f20(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%20.12E", v);
  return b;
}

// Two unit squares: one /SHELL quad (part 1) and two /SH3N triangles (part 2).
std::string starter(const std::string& prop_line1, const std::string& prop_line3,
                    double part_thick, double elem_thick, const std::string& mat_card) {
  std::string s = "#RADIOSS STARTER\n/BEGIN\nshell_build\n      2024         0\n";
  s += "                  kg                  mm                  ms\n";
  s += "                  kg                  mm                  ms\n/NODE\n";
  const double xy[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}};
  for (int n = 0; n < 6; ++n) s += i10(n + 1) + f20(xy[n][0]) + f20(xy[n][1]) + f20(0) + "\n";
  s += mat_card;
  s += "/PROP/TYPE1/1\nplate\n" + prop_line1 + "\n" + f20(0.01) + f20(0.01) + f20(0.01) + f20(0) + f20(0) +
       "\n" + prop_line3 + "\n";
  s += "/PART/1\nquad part\n" + i10(1) + i10(1) + i10(0) + f20(part_thick) + "\n";
  s += "/PART/2\ntria part\n" + i10(1) + i10(1) + i10(0) + "\n";
  s += "/SHELL/1\n" + i10(1) + i10(1) + i10(2) + i10(3) + i10(4) + std::string(10, ' ') + f20(0) +
       f20(elem_thick) + "\n";
  s += "/SH3N/2\n" + i10(2) + i10(2) + i10(5) + i10(6) + "\n" + i10(3) + i10(2) + i10(6) + i10(3) + "\n";
  s += "/END\n";
  return s;
}

const std::string kLaw1 = "/MAT/LAW1/1\nsteel\n" + f20(7.85e-6) + "\n" + f20(210) + f20(0.3) + "\n";
const std::string kLine1 = i10(0) + i10(0) + i10(0) + i10(0) + i10(0);
const std::string kLine3 = i10(3) + i10(0) + f20(2.0) + f20(5.0 / 6.0);

struct Built {
  bool ok = false;
  std::vector<std::string> messages;
  Model model;
};

std::unique_ptr<Built> build(const std::string& st) {
  auto b = std::make_unique<Built>();
  auto rs = hbm::deck::read_deck_text(st, "shell_build_0000.rad", hbm::deck::Section::Starter);
  auto re = hbm::deck::read_deck_text("#RADIOSS ENGINE\n/RUN/shell_build/1\n1.0\n", "shell_build_0001.rad",
                                      hbm::deck::Section::Engine);
  EXPECT_TRUE(rs.ok()) << (rs.diagnostics.empty() ? "" : rs.diagnostics.front().message);
  EXPECT_TRUE(re.ok());
  static std::vector<hbm::deck::ReadResult> keep;  // the model refers to the decks
  keep.push_back(std::move(rs));
  keep.push_back(std::move(re));
  b->ok = build_model(keep[keep.size() - 2].deck, keep.back().deck, b->model, b->messages);
  return b;
}

std::string all(const std::vector<std::string>& m) {
  std::string s;
  for (const auto& x : m) s += x + "\n";
  return s;
}

}  // namespace

TEST(ShellBuilder, GroupsThicknessMassAndRotations) {
  const auto b = build(starter(kLine1, kLine3, 1.5, 0.7, kLaw1));
  ASSERT_TRUE(b->ok) << all(b->messages);
  const shells::ShellElementGroup* quad = nullptr;
  const shells::ShellElementGroup* tria = nullptr;
  for (const auto& g : b->model.groups) {
    if (auto* s = dynamic_cast<const shells::ShellElementGroup*>(g.get()))
      (s->keyword == "/SHELL" ? quad : tria) = s;
  }
  ASSERT_TRUE(quad && tria);
  EXPECT_EQ(quad->n_elements, 1u);
  EXPECT_EQ(tria->n_elements, 2u);
  EXPECT_DOUBLE_EQ(quad->data.thick[0], 0.7);  // element thickness wins
  EXPECT_DOUBLE_EQ(tria->data.thick[0], 2.0);  // part 2 has none: property's
  EXPECT_EQ(quad->data.sec.n_points, 3);
  // Total nodal mass = rho (0.7 * 1 + 2.0 * 1).
  double m = 0;
  for (double v : b->model.nodes.mass0) m += v;
  EXPECT_NEAR(m, 7.85e-6 * (0.7 + 2.0), 1e-15);
  for (std::size_t n = 0; n < 6; ++n) EXPECT_EQ(b->model.nodes.has_rotation[n], 1);
}

TEST(ShellBuilder, RefusesUnsupportedFormulationNamingTheField) {
  const std::string line1 = i10(12) + i10(0) + i10(0) + i10(0) + i10(0);
  const auto b = build(starter(line1, kLine3, 0, 0, kLaw1));
  EXPECT_FALSE(b->ok);
  const std::string msg = all(b->messages);
  EXPECT_NE(msg.find("Ishell"), std::string::npos) << msg;
  EXPECT_NE(msg.find("shell_build_0000.rad:"), std::string::npos) << msg;
}

TEST(ShellBuilder, RefusesOffsetReferencePlaneNamingTheField) {
  // Ipos (line 3, columns 91-100) = 1: offset shells are not supported.
  const std::string line3 = kLine3 + std::string(10, ' ') + i10(0) + i10(0) + i10(1);
  const auto b = build(starter(kLine1, line3, 0, 0, kLaw1));
  EXPECT_FALSE(b->ok);
  const std::string msg = all(b->messages);
  EXPECT_NE(msg.find("Ipos"), std::string::npos) << msg;
  EXPECT_NE(msg.find("/PROP/TYPE1"), std::string::npos) << msg;
}

// Hourglass coefficients typed 0 or blank take OpenRadioss's defaults (hm_read_prop01.F):
// Hm = Hf = 0.1 and Hr = 0.01 for Ishell 3, 0.01 for the others; typed values are kept.
TEST(ShellBuilder, HourglassDefaultsAsOpenRadioss) {
  const std::string typed = f20(0.01) + f20(0.01) + f20(0.01);
  auto coefficients = [&](int ishell, const std::string& line2) {
    std::string st = starter(i10(ishell) + i10(0) + i10(0) + i10(0) + i10(0), kLine3, 0, 0, kLaw1);
    const auto pos = st.find(typed);
    EXPECT_NE(pos, std::string::npos);
    st.replace(pos, typed.size(), line2);
    const auto b = build(st);
    EXPECT_TRUE(b->ok) << all(b->messages);
    for (const auto& g : b->model.groups)
      if (auto* s = dynamic_cast<const shells::ShellElementGroup*>(g.get()))
        return std::array<double, 3>{s->data.sec.hm, s->data.sec.hf, s->data.sec.hr};
    ADD_FAILURE() << "no shell group";
    return std::array<double, 3>{};
  };
  const std::string blank(60, ' ');
  EXPECT_EQ(coefficients(3, blank), (std::array<double, 3>{0.1, 0.1, 0.01}));
  EXPECT_EQ(coefficients(4, blank), (std::array<double, 3>{0.01, 0.01, 0.01}));
  EXPECT_EQ(coefficients(0, f20(0) + f20(0) + f20(0)), (std::array<double, 3>{0.01, 0.01, 0.01}));
  EXPECT_EQ(coefficients(3, f20(0.02) + f20(0.03) + f20(0.04)), (std::array<double, 3>{0.02, 0.03, 0.04}));
}
