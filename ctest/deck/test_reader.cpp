// SPDX-License-Identifier: GPL-3.0-or-later
// Reader tests on the small valid decks in ctest/deck/decks: every value asserted here is
// the one typed in the deck file (including Fortran and Radioss exponent forms and a
// node from an #include'd file).
#include "deck_test_support.hpp"
#include "hbm/deck/io.hpp"

#include <gtest/gtest.h>

#include <sstream>

using namespace hbm::deck;
using hbm::deck::testing::kDir;
using hbm::deck::testing::messages;

namespace {

const Row* node_row(const Deck& d, std::int64_t id) {
  for (const Card* c : d.cards_of("/NODE"))
    for (std::size_t i = 0; i < c->n_rows(); ++i)
      if (c->integer(c->row(i), "id") == id) return &c->row(i);
  return nullptr;
}

}  // namespace

TEST(DeckReader, SmallStarterReadsCleanly) {
  const ReadResult r = read_deck(kDir / "small_0000.rad", Section::Starter);
  ASSERT_TRUE(r.ok()) << messages(r);
  EXPECT_EQ(r.diagnostics.size(), 0u) << messages(r);
  EXPECT_EQ(r.deck.run_name, "small");
  EXPECT_EQ(r.deck.invers, 2024);
  EXPECT_EQ(r.deck.work_units.mass, "kg");
  EXPECT_EQ(r.deck.work_units.length, "mm");
  EXPECT_EQ(r.deck.work_units.time, "ms");
  ASSERT_EQ(r.deck.files.size(), 2u);  // main deck + small_nodes.inc
  EXPECT_EQ(r.deck.files[1].filename(), "small_nodes.inc");
}

TEST(DeckReader, NodeCoordinatesIncludingExponentFormsAndIncludes) {
  const ReadResult r = read_deck(kDir / "small_0000.rad", Section::Starter);
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto nodes = r.deck.cards_of("/NODE");
  ASSERT_EQ(nodes.size(), 1u);
  EXPECT_EQ(nodes[0]->n_rows(), 11u);  // 10 in the deck + 1 from the include
  const Card& c = *nodes[0];
  const Row* n7 = node_row(r.deck, 7);
  ASSERT_NE(n7, nullptr);
  EXPECT_DOUBLE_EQ(c.real(*n7, "X"), 10.0);
  EXPECT_DOUBLE_EQ(c.real(*n7, "Y"), 10.0);
  EXPECT_DOUBLE_EQ(c.real(*n7, "Z"), 10.0);
  EXPECT_DOUBLE_EQ(c.real(*node_row(r.deck, 9), "Z"), 15.0);   // 1.5D1
  EXPECT_DOUBLE_EQ(c.real(*node_row(r.deck, 10), "Z"), 15.0);  // 1.5E+01
  const Row* n11 = node_row(r.deck, 11);
  ASSERT_NE(n11, nullptr);
  EXPECT_DOUBLE_EQ(c.real(*n11, "X"), 30.0);
  EXPECT_EQ(n11->loc.file, 1u);
  EXPECT_EQ(n11->loc.line, 2u);
  EXPECT_EQ(r.deck.where(n11->loc), (kDir / "small_nodes.inc").string() + ":2");
}

TEST(DeckReader, ElementsPartsPropertiesMaterials) {
  const ReadResult r = read_deck(kDir / "small_0000.rad", Section::Starter);
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto bricks = r.deck.cards_of("/BRICK");
  ASSERT_EQ(bricks.size(), 1u);
  EXPECT_EQ(bricks[0]->id, 1);  // part id
  ASSERT_EQ(bricks[0]->n_rows(), 1u);
  EXPECT_EQ(bricks[0]->integer(bricks[0]->row(0), "id"), 101);
  EXPECT_EQ(bricks[0]->integer(bricks[0]->row(0), "n8"), 8);
  const Card& shell = *r.deck.cards_of("/SHELL")[0];
  EXPECT_DOUBLE_EQ(shell.real(shell.row(0), "thick"), 0.5);
  EXPECT_DOUBLE_EQ(shell.real(shell.row(0), "Thick"), 0.5);  // names are case-insensitive
  const Card& tri = *r.deck.cards_of("/SH3N")[0];
  EXPECT_TRUE(tri.blank(tri.row(0), "thick"));
  EXPECT_DOUBLE_EQ(tri.real(tri.row(0), "thick"), 0.0);
  const Card& part3 = *r.deck.cards_of("/PART")[2];
  EXPECT_EQ(part3.id, 3);
  EXPECT_EQ(part3.title, "shell part");
  EXPECT_EQ(part3.integer(0, "prop_id"), 3);
  EXPECT_EQ(part3.integer(0, "mat_id"), 1);
  const Card& steel = *r.deck.cards_of("/MAT/LAW1")[0];
  EXPECT_DOUBLE_EQ(steel.real(0, "rho"), 7.8e-6);
  EXPECT_DOUBLE_EQ(steel.real(1, "E"), 210.0);
  EXPECT_DOUBLE_EQ(steel.real(1, "nu"), 0.3);
  const Card& brain = *r.deck.cards_of("/MAT/LAW34")[0];
  EXPECT_DOUBLE_EQ(brain.real(0, "rho"), 1.04e-6);  // Radioss form 1.04-6
  EXPECT_DOUBLE_EQ(brain.real(1, "K"), 2.19);
  EXPECT_DOUBLE_EQ(brain.real(2, "G0"), 5.28e-4);
  EXPECT_DOUBLE_EQ(brain.real(2, "Ginf"), 1.68e-4);
  EXPECT_DOUBLE_EQ(brain.real(2, "beta"), 0.035);
  EXPECT_DOUBLE_EQ(brain.real(3, "P0"), 0.0);  // optional line absent
  const Card& solid = *r.deck.cards_of("/PROP/TYPE14")[0];
  EXPECT_DOUBLE_EQ(solid.real(1, "qa"), 1.1);
  EXPECT_DOUBLE_EQ(solid.real(1, "h"), 0.1);
  const Card& spring = *r.deck.cards_of("/PROP/TYPE4")[0];
  EXPECT_DOUBLE_EQ(spring.real(0, "Mass"), 0.001);
  EXPECT_DOUBLE_EQ(spring.real(1, "K"), 10.0);
  EXPECT_DOUBLE_EQ(spring.real(1, "A"), 1.0);  // blank: default 1
  const Card& shellprop = *r.deck.cards_of("/PROP/TYPE1")[0];
  EXPECT_EQ(shellprop.integer(2, "N"), 5);
  EXPECT_DOUBLE_EQ(shellprop.real(2, "Thick"), 1.2);
}

TEST(DeckReader, LoadsGroupsFunctionsTimeHistory) {
  const ReadResult r = read_deck(kDir / "small_0000.rad", Section::Starter);
  ASSERT_TRUE(r.ok()) << messages(r);
  const Deck& d = r.deck;
  const Card& bcs = *d.cards_of("/BCS")[0];
  EXPECT_EQ(d.text(bcs, bcs.lines[0], "Tra"), "111");
  EXPECT_EQ(d.text(bcs, bcs.lines[0], "rot"), "111");
  EXPECT_EQ(bcs.integer(0, "grnod_id"), 1);
  const Card& grn = *d.cards_of("/GRNOD/NODE")[0];
  ASSERT_EQ(grn.n_rows(), 1u);
  EXPECT_EQ(grn.integer(grn.row(0), "id4"), 4);
  EXPECT_TRUE(grn.blank(grn.row(0), "id5"));
  const Card& fn = *d.cards_of("/FUNCT")[0];
  ASSERT_EQ(fn.n_rows(), 2u);
  EXPECT_DOUBLE_EQ(fn.real(fn.row(1), "X"), 1.0);
  EXPECT_DOUBLE_EQ(fn.real(fn.row(1), "Y"), 0.02);
  const Card& grav = *d.cards_of("/GRAV")[0];
  EXPECT_EQ(d.text(grav, grav.lines[0], "Dir"), "Z");
  EXPECT_DOUBLE_EQ(grav.real(1, "Fscale_y"), -9.81e-6);
  const Card& iv = *d.cards_of("/INIVEL/TRA")[0];
  EXPECT_DOUBLE_EQ(iv.real(0, "Vz"), -1000.0);
  EXPECT_EQ(iv.integer(0, "grnod_id"), 2);
  const Card& thn = *d.cards_of("/TH/NODE")[0];
  ASSERT_EQ(thn.n_name_rows(), 1u);
  EXPECT_EQ(d.text(thn, thn.name_row(0), "var1"), "DEF");
  EXPECT_EQ(d.text(thn, thn.name_row(0), "var2"), "DX");
  ASSERT_EQ(thn.n_rows(), 1u);
  EXPECT_EQ(thn.integer(thn.row(0), "node_id"), 7);
  EXPECT_EQ(d.text(thn, thn.row(0), "name"), "top corner");
  const Card& thp = *d.cards_of("/TH/PART")[0];
  EXPECT_EQ(thp.integer(thp.row(0), "id3"), 3);
}

TEST(DeckReader, EngineDeckFreeFormat) {
  const ReadResult r = read_deck(kDir / "small_0001.rad", Section::Engine);
  ASSERT_TRUE(r.ok()) << messages(r);
  const Deck& d = r.deck;
  EXPECT_EQ(d.run_name, "small");
  const Card& run = *d.cards_of("/RUN")[0];
  EXPECT_EQ(run.id, 1);
  EXPECT_DOUBLE_EQ(run.real(0, "Tstop"), 10.0);
  EXPECT_DOUBLE_EQ(d.cards_of("/TFILE")[0]->real(0, "dt_his"), 0.01);
  EXPECT_EQ(d.cards_of("/TFILE")[0]->id, 4);
  EXPECT_DOUBLE_EQ(d.cards_of("/ANIM/DT")[0]->real(0, "Tfreq"), 1.0);
  EXPECT_EQ(d.cards_of("/ANIM/VECT/VEL").size(), 1u);
  EXPECT_EQ(d.cards_of("/ANIM/ELEM/VONM").size(), 1u);
  EXPECT_EQ(d.cards_of("/ANIM/NODA/DMAS").size(), 1u);
  const Card& dt = *d.cards_of("/DT/NODA/CST")[0];
  EXPECT_DOUBLE_EQ(dt.real(0, "Tsca"), 0.9);
  EXPECT_DOUBLE_EQ(dt.real(0, "Tmin"), 1.5e-3);
  const Card& stop = *d.cards_of("/STOP")[0];
  EXPECT_DOUBLE_EQ(stop.real(0, "DMmax"), 0.01);
  EXPECT_EQ(stop.integer(0, "NANIM"), 1);
  EXPECT_EQ(d.cards_of("/PRINT")[0]->id, -100);
}

TEST(DeckReader, UnknownFieldNameThrows) {
  const ReadResult r = read_deck(kDir / "small_0000.rad", Section::Starter);
  const Card& steel = *r.deck.cards_of("/MAT/LAW1")[0];
  EXPECT_THROW((void)steel.real(1, "Young"), std::out_of_range);
}

TEST(DeckReader, RigidBodiesSurfacesContactsWallsSprings) {
  const ReadResult r = read_deck(kDir / "small_0000.rad", Section::Starter);
  ASSERT_TRUE(r.ok()) << messages(r);
  const Deck& d = r.deck;
  const Card& t8 = *d.cards_of("/PROP/TYPE8")[0];
  EXPECT_DOUBLE_EQ(t8.real(0, "Mass"), 0.002);
  EXPECT_DOUBLE_EQ(t8.real(0, "Inertia"), 1e-3);
  EXPECT_DOUBLE_EQ(t8.real(1, "K1"), 100.0);
  EXPECT_DOUBLE_EQ(t8.real(1, "C1"), 0.1);
  EXPECT_DOUBLE_EQ(t8.real(4, "K2"), 200.0);
  EXPECT_DOUBLE_EQ(t8.real(7, "K3"), 300.0);
  EXPECT_DOUBLE_EQ(t8.real(10, "K4"), 0.0);   // absent block
  EXPECT_DOUBLE_EQ(t8.real(12, "Ascale4"), 1.0);  // default of an absent line
  const Card& t13 = *d.cards_of("/PROP/TYPE13")[0];
  EXPECT_DOUBLE_EQ(t13.real(1, "K1"), 50.0);
  const Card& rb = *d.cards_of("/RBODY")[0];
  EXPECT_EQ(rb.integer(0, "node_id"), 11);
  EXPECT_DOUBLE_EQ(rb.real(0, "Mass"), 0.5);
  EXPECT_EQ(rb.integer(0, "grnod_id"), 1);
  EXPECT_DOUBLE_EQ(rb.real(1, "Jzz"), 3.0);
  const Card& seg = *d.cards_of("/SURF/SEG")[0];
  EXPECT_EQ(seg.integer(seg.row(0), "n4"), 2);
  const Card& i7 = *d.cards_of("/INTER/TYPE7")[0];
  EXPECT_EQ(i7.integer(0, "grnod_id"), 2);
  EXPECT_EQ(i7.integer(0, "surf_id"), 1);
  EXPECT_DOUBLE_EQ(i7.real(3, "Stfac"), 1.0);
  EXPECT_DOUBLE_EQ(i7.real(3, "Fric"), 0.2);
  EXPECT_DOUBLE_EQ(i7.real(3, "Gapmin"), 0.5);
  EXPECT_DOUBLE_EQ(i7.real(4, "Bumult"), 0.2);
  EXPECT_EQ(d.text(i7, i7.lines[4], "IBC"), "000");
  const Card& i2 = *d.cards_of("/INTER/TYPE2")[0];
  EXPECT_DOUBLE_EQ(i2.real(0, "dsearch"), 0.5);
  const Card& wall = *d.cards_of("/RWALL/PLANE")[0];
  EXPECT_EQ(wall.integer(0, "grnod_id1"), 2);
  EXPECT_DOUBLE_EQ(wall.real(1, "fric"), 0.1);
  EXPECT_DOUBLE_EQ(wall.real(2, "ZM"), -5.0);
  EXPECT_DOUBLE_EQ(wall.real(3, "ZM1"), 0.0);
  const Card& ths = *d.cards_of("/TH/INTER")[0];
  EXPECT_EQ(ths.integer(ths.row(0), "id2"), 2);
  EXPECT_EQ(d.cards_of("/TH/RWALL")[0]->integer(d.cards_of("/TH/RWALL")[0]->row(0), "id1"), 1);
}
