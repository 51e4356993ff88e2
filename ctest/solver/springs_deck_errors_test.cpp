// SPDX-License-Identifier: GPL-3.0-or-later
// Bad spring and rigid-body input stops hbm-solver in the build phase with exit code 1 and
// a message naming file:line, keyword and field: an unsupported hardening flag, a
// hardening rule without its curve, a rotational spring without inertia, a spring joining
// a node to itself, a rigid body on an empty or overlapping node group. The decks are the
// verification deck springs_mass_period / rigid_tumbling with one field changed.
#include "example_deck_runner.hpp"

#include <string>

namespace {

int run_modified(const std::string& name, const std::string& tag, const std::string& from,
                 const std::string& to, std::string& output) {
  return hbm::solver::testing::run_modified_deck(name, tag, from, to, output);
}

const std::string kDofLine = "         0         0         0         0         0";

}  // namespace

TEST(SpringDeckErrors, UnsupportedHardeningFlag) {
  std::string out;
  EXPECT_EQ(run_modified("springs_mass_period", "h5", kDofLine, "         0         5         0         0         0", out), 1);
  EXPECT_NE(out.find("springs_mass_period_0000.rad:"), std::string::npos) << out;
  EXPECT_NE(out.find("/PROP/TYPE4/1 field H"), std::string::npos) << out;
  EXPECT_NE(out.find("not supported"), std::string::npos) << out;
}

TEST(SpringDeckErrors, HardeningWithoutCurve) {
  std::string out;
  EXPECT_EQ(run_modified("springs_mass_period", "h1", kDofLine, "         0         1         0         0         0", out), 1);
  EXPECT_NE(out.find("/PROP/TYPE4/1 field fct_id1"), std::string::npos) << out;
}

TEST(SpringDeckErrors, SpringOnOneNode) {
  std::string out;
  EXPECT_EQ(run_modified("springs_mass_period", "self", "         1         1         2\n",
                         "         1         2         2\n", out), 1);
  EXPECT_NE(out.find("/SPRING/1 field n2"), std::string::npos) << out;
  EXPECT_NE(out.find("to itself"), std::string::npos) << out;
}

// Inertia 0 reads as OpenRadioss reads it (1e-20, a warning): the torsion deck runs to its end,
// its node's rotation held by the inertia /DT/NODA/CST adds.
TEST(SpringDeckErrors, RotationalSpringWithoutInertiaGetsOpenRadiossMinimum) {
  std::string out;
  // springs_torsion: line 1 of the TYPE8 property, Inertia 4 -> 0.
  EXPECT_EQ(run_modified("springs_torsion", "noinertia", "  2.000000000000E+00  4.000000000000E+00",
                         "  2.000000000000E+00  0.000000000000E+00", out), 0) << out;
  EXPECT_NE(out.find("Inertia <= 1e-20 is set to 1e-20, as in OpenRadioss"), std::string::npos) << out;
  EXPECT_NE(out.find("NORMAL TERMINATION"), std::string::npos) << out;
}

TEST(RigidDeckErrors, SecondaryNodeInTwoBodies) {
  std::string out;
  // rigid_intermediate_axis: body 2's secondary group (nodes 10..17) -> body 1's nodes.
  EXPECT_EQ(run_modified("rigid_intermediate_axis", "overlap",
                         "        10        11        12        13        14        15        16        17",
                         "         1         2         3         4         5         6         7         8", out), 1);
  EXPECT_NE(out.find("/RBODY/2 field grnod_id"), std::string::npos) << out;
  EXPECT_NE(out.find("already a node of another rigid body"), std::string::npos) << out;
}
