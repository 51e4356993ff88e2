// SPDX-License-Identifier: GPL-3.0-or-later
// Kinematic conditions that cannot act on rigid-body secondary nodes stop hbm-solver in
// the build phase with exit code 1 and a message naming file:line, keyword and field:
//  - /BCS (or /IMPVEL) on a secondary node of an /RBODY: the body imposes the node's
//    velocity after those constraints, the condition would be silently lost
//  - a moving /RWALL/PLANE whose secondaries include rigid-body secondaries
// The decks are the verification deck rigid_rwall_impact with one card added or changed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Copy rigid_rwall_impact with `from` replaced by `to` in the starter, run it, return the
// exit code and the solver's output.
int run_modified(const std::string& tag, const std::string& from, const std::string& to, std::string& output) {
  const std::string name = "rigid_rwall_impact";
  const std::filesystem::path src = std::filesystem::path(HBM_SOURCE_DIR) / "decks/examples" / name;
  const std::filesystem::path dir = std::filesystem::current_path() / ("bad_" + tag);
  std::filesystem::create_directories(dir);
  std::string starter = slurp(src / (name + "_0000.rad"));
  const auto pos = starter.find(from);
  EXPECT_NE(pos, std::string::npos) << "pattern not in deck: " << from;
  if (pos != std::string::npos) starter.replace(pos, from.size(), to);
  std::ofstream(dir / (name + "_0000.rad")) << starter;
  std::filesystem::copy_file(src / (name + "_0001.rad"), dir / (name + "_0001.rad"),
                             std::filesystem::copy_options::overwrite_existing);
#ifdef HBM_SOLVER_EXE
  const std::string log = (dir / "log.txt").string();
  const std::string cmd = std::string(HBM_SOLVER_EXE) + " " + (dir / (name + "_0000.rad")).string() +
                          " --out " + (dir / "out").string() + " > " + log + " 2>&1";
  const int rc = std::system(cmd.c_str());
  output = slurp(log);
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
#else
  ADD_FAILURE() << "hbm-solver was not built";
  return -1;
#endif
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
