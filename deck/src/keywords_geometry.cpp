// SPDX-License-Identifier: GPL-3.0-or-later
// Keyword tables of the starter's frame and geometry cards: /BEGIN, /END, /TITLE, /NODE
// and the element blocks /BRICK, /TETRA4, /SHELL, /SH3N, /SPRING. Layouts follow the
// Radioss 2024 reference guide (block format); field names are the API of Card::real() etc.
#include "field_builders.hpp"

namespace hbm::deck::tables {

namespace {

KeywordSpec card(std::string_view kw, IdKind id, bool title, std::string_view meaning) {
  return keyword(kw, Section::Starter, id, title, meaning);
}

FieldSpec node_ref(std::string_view name, int col, bool required, std::string_view meaning) {
  return id_field(name, col, RefKind::Node, required, meaning);
}

// Element line of a solid or shell block: element id, n_nodes required node ids n1..n8
// (10 columns each), then `more` fields.
LineSpec element_row(int n_nodes, std::vector<FieldSpec> more = {}) {
  static constexpr std::string_view names[] = {"n1", "n2", "n3", "n4", "n5", "n6", "n7", "n8"};
  std::vector<FieldSpec> f{own_id("id", 0, "element identifier")};
  for (int i = 0; i < n_nodes; ++i) f.push_back(node_ref(names[i], 10 + 10 * i, true, "node"));
  for (FieldSpec& m : more) f.push_back(std::move(m));
  return line("element", std::move(f));
}

// Shell element line: the nodes, then orientation angle and thickness.
LineSpec shell_row(int n_nodes) {
  return element_row(n_nodes, {
      real_field("phi", 60, Dimension::Angle, kAny, 0, "orthotropy angle (deg)"),
      real_field("thick", 80, Dimension::Length, kNonNegative, 0, "thickness (0: the part's, else the property's)"),
  });
}

}  // namespace

void add_starter_geometry(std::vector<KeywordSpec>& out) {
  {
    KeywordSpec k = card("/BEGIN", IdKind::None, true,
                         "First card of the starter deck: run name (title line), version, units.");
    k.lines.push_back(line("version", {
        int_field("Invers", 0, 2017, 2100, 2024, "input format version (2024)", Dimension::Count),
        int_field("Irun", 10, 0, 99, 0, "run number (0 = new run)", Dimension::Count),
    }));
    k.lines.push_back(line("input units", {
        text_field("mass", 0, 20, "input mass unit (kg, g, Mg, t, lb)"),
        text_field("length", 20, 20, "input length unit (mm, m, cm)"),
        text_field("time", 40, 20, "input time unit (ms, s, us)"),
    }));
    k.lines.push_back(line("work units", {
        text_field("mass", 0, 20, "work mass unit"),
        text_field("length", 20, 20, "work length unit"),
        text_field("time", 40, 20, "work time unit"),
    }));
    out.push_back(std::move(k));
  }
  out.push_back(card("/END", IdKind::None, false, "Last card of the starter deck."));
  out.push_back(card("/TITLE", IdKind::None, true, "Model title (one free line)."));
  {
    KeywordSpec k = card("/NODE", IdKind::None, false, "Nodes: one node per line.");
    k.rows = line("node", {
        own_id("id", 0, "node identifier"),
        real_field("X", 10, Dimension::Length, kAny, 0, "X coordinate"),
        real_field("Y", 30, Dimension::Length, kAny, 0, "Y coordinate"),
        real_field("Z", 50, Dimension::Length, kAny, 0, "Z coordinate"),
    });
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/BRICK", IdKind::Part, false,
                         "8-node solid elements of part part_id (keyword id). n1-n4 one face, "
                         "n5-n8 the opposite face, positive Jacobian.");
    k.rows = element_row(8);
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/TETRA4", IdKind::Part, false,
                         "4-node tetrahedra of part part_id; (n2-n1)x(n3-n1).(n4-n1) > 0.");
    k.rows = element_row(4);
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/SHELL", IdKind::Part, false, "4-node shells of part part_id.");
    k.rows = shell_row(4);
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/SH3N", IdKind::Part, false, "3-node shells of part part_id.");
    k.rows = shell_row(3);
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/SPRING", IdKind::Part, false,
                         "Spring elements of part part_id (property TYPE4, TYPE8 or TYPE13).");
    k.rows = line("element", {
        own_id("id", 0, "element identifier"),
        node_ref("n1", 10, true, "node 1"),
        node_ref("n2", 20, true, "node 2"),
        node_ref("n3", 30, false, "orientation node (TYPE13), optional"),
        id_field("skew_id", 70, RefKind::Skew, false, "skew system (TYPE8), optional"),
    });
    out.push_back(std::move(k));
  }
}

}  // namespace hbm::deck::tables
