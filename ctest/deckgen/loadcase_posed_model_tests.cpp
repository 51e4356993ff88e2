// SPDX-License-Identifier: GPL-3.0-or-later
// The oblique thorax load cases on the posed model (left arm raised out of the impactor's
// path, decks/hub_posed_arm_l_raised/): the committed variant equals the committed base
// model except for the arm, a stale variant is refused with the command that rewrites it,
// and the generated oblique deck has nothing in the impactor's path but contact parts.
#include "hbm/deckgen/loadcases/load_case.hpp"
#include "hbm/deckgen/loadcases/posed_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;
namespace lc = hbm::deckgen::loadcases;

namespace {

const fs::path kSource = HBM_SOURCE_DIR;
const fs::path kBase = kSource / "decks/hbm50/hbm50.inc";

const lc::LoadCaseSpec& oblique() {
  const lc::LoadCaseSpec* s = lc::find_case("hub_oblique_6p5");
  if (!s) throw std::logic_error("hub_oblique_6p5 not in the catalogue");
  return *s;
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("hbm_loadcase_posed_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(LoadCasePosedModel, CommittedVariantIsTheBaseModelWithTheArmMoved) {
  const auto& spec = oblique();
  const fs::path posed_path = lc::posed_model_path(kBase, spec.posed_model);
  ASSERT_TRUE(fs::exists(posed_path)) << posed_path;
  const lc::ModelView base = lc::read_model(kBase), posed = lc::read_model(posed_path);
  EXPECT_NO_THROW(lc::check_posed_model(base, posed, spec.posed_part_prefixes, spec.posed_model_command()));
  // The arm did move: a 60 deg turn about the shoulder moves every arm node (the nearest to
  // the joint axis by a few mm) and the hand by more than the arm's 300 mm reach times 2 sin 30.
  double farthest = 0;
  for (auto pid : base.parts_with_prefix({"upper_arm_l", "forearm_hand_l"}))
    for (auto n : base.part_nodes.at(pid)) {
      const double moved = (posed.nodes.at(n) - base.nodes.at(n)).norm();
      EXPECT_GT(moved, 1.0) << "node " << n;
      farthest = std::max(farthest, moved);
    }
  EXPECT_GT(farthest, 300.0);
}

TEST(LoadCasePosedModel, StaleVariantIsRefused) {
  const auto& spec = oblique();
  const fs::path dir = scratch("stale");
  // The committed variant with node 1 (a trunk node) moved by 1 mm in X.
  std::ifstream in(lc::posed_model_path(kBase, spec.posed_model));
  std::ostringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string line = "\n         1                -102               -37.5                -100\n";
  const auto at = s.find(line);
  ASSERT_NE(at, std::string::npos);
  s.replace(at, line.size(), "\n         1                -101               -37.5                -100\n");
  std::ofstream(dir / "stale.inc") << s;
  const lc::ModelView base = lc::read_model(kBase), stale = lc::read_model(dir / "stale.inc");
  try {
    lc::check_posed_model(base, stale, spec.posed_part_prefixes, spec.posed_model_command());
    FAIL() << "a stale posed model was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("node 1 of part"), std::string::npos) << what;
    EXPECT_NE(what.find("--joint shoulder_l=-60"), std::string::npos) << what;
  }
  fs::remove_all(dir.parent_path());
}

TEST(LoadCasePosedModel, ObliqueImpactorPathHoldsOnlyContactParts) {
  const auto& spec = oblique();
  const fs::path posed_path = lc::posed_model_path(kBase, spec.posed_model);
  const fs::path dir = scratch("oblique");
  const lc::GeneratedCase g = lc::generate_load_case(spec, lc::read_model(posed_path), posed_path, kSource / "geometry", dir / spec.name);
  EXPECT_TRUE(g.warnings.empty()) << g.warnings.front();  // no part passed through
  EXPECT_EQ(g.nearest_part.rfind("skin_", 0), 0u) << g.nearest_part;  // the chest is struck first
  EXPECT_GT(g.limb_contact_nodes, 0u);                                  // the arm stays in the contact
  // On the base (driver posture) model the forearm is struck first, far ahead of the skin.
  const lc::GeneratedCase d = lc::generate_load_case(spec, lc::read_model(kBase), kBase, kSource / "geometry", dir / "driver");
  EXPECT_EQ(d.nearest_part, "forearm_hand_l");
  EXPECT_GT((d.face_centre - g.face_centre).norm(), 100.0);
  fs::remove_all(dir.parent_path());
}
