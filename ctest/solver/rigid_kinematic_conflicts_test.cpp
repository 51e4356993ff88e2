// SPDX-License-Identifier: GPL-3.0-or-later
// Kinematic conditions that cannot act on rigid-body secondary nodes stop hbm-solver in
// the build phase with exit code 1 and a message naming file:line, keyword and field:
//  - /BCS (or /IMPVEL) on a secondary node of an /RBODY: the body imposes the node's
//    velocity after those constraints, the condition would be silently lost
//  - a moving /RWALL/PLANE whose secondaries include rigid-body secondaries
// The decks are the verification deck rigid_rwall_impact with one card added or changed.
#include "example_deck_runner.hpp"

#include <string>

namespace {

int run_modified(const std::string& tag, const std::string& from, const std::string& to, std::string& output) {
  return hbm::solver::testing::run_modified_deck("rigid_rwall_impact", tag, from, to, output);
}

// Node 21 is the lowest corner of body 2 (a secondary of /RBODY/2; main node 28).
const std::string kGroup = "/GRNOD/NODE/90\ncorner of the bar\n        21\n";

}  // namespace

TEST(RigidKinematicConflicts, BcsOnRigidBodySecondaryNode) {
  std::string out;
  EXPECT_EQ(run_modified("bcs", "/TH/RBODY/1", kGroup + "/BCS/7\ncorner fixed\n   111 000         0        90\n/TH/RBODY/1",
                         out),
            1);
  EXPECT_NE(out.find("rigid_rwall_impact_0000.rad:"), std::string::npos) << out;
  EXPECT_NE(out.find("/BCS/7 field grnod_id"), std::string::npos) << out;
  EXPECT_NE(out.find("node 21 is a secondary node of /RBODY/2"), std::string::npos) << out;
  EXPECT_NE(out.find("main node 28"), std::string::npos) << out;
}

TEST(RigidKinematicConflicts, BcsOnRigidBodyMainNodeIsAccepted) {
  std::string out;
  const std::string group = "/GRNOD/NODE/90\nmain node of the bar\n        28\n";
  EXPECT_EQ(run_modified("bcs_main", "/TH/RBODY/1", group + "/BCS/7\nbar fixed\n   111 000         0        90\n/TH/RBODY/1",
                         out),
            0)
      << out;
}

TEST(RigidKinematicConflicts, MovingWallOnRigidBodySecondaries) {
  std::string out;
  // Wall 3 (under body 3) made a moving wall carried by node 19 (the flat box's main node).
  EXPECT_EQ(run_modified("moving_wall", "         0         1         5         0",
                         "        19         1         5         0", out),
            1);
  EXPECT_NE(out.find("rigid_rwall_impact_0000.rad:"), std::string::npos) << out;
  EXPECT_NE(out.find("/RWALL/PLANE/3 field node_id"), std::string::npos) << out;
  EXPECT_NE(out.find("not supported"), std::string::npos) << out;
}
