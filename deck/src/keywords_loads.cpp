// SPDX-License-Identifier: GPL-3.0-or-later
// Keyword tables of groups, surfaces, functions, boundary conditions, loads, contacts,
// rigid bodies and time-history requests (/GRNOD, /SURF, /FUNCT, /BCS, /IMPVEL,
// /INIVEL/TRA, /GRAV, /RBODY, /INTER, /RWALL/PLANE, /TH/*). Radioss 2024 block format.
#include "field_builders.hpp"

#include <array>

namespace hbm::deck::tables {

namespace {

constexpr std::array<std::string_view, 10> kVarNames = {"var1", "var2", "var3", "var4", "var5",
                                                        "var6", "var7", "var8", "var9", "var10"};

// A line of up to 10 ids (10 columns each), blank = no entry.
LineSpec id_list(std::string_view name, RefKind ref, std::string_view what) {
  std::vector<FieldSpec> f;
  for (int i = 0; i < 10; ++i) f.push_back(id_field(kIdNames[i], 10 * i, ref, false, what));
  return line(name, std::move(f));
}

LineSpec var_list() {
  std::vector<FieldSpec> f;
  for (int i = 0; i < 10; ++i)
    f.push_back(text_field(kVarNames[i], 10 * i, 10, "output variable name (DEF = default set)"));
  return line("variables", std::move(f));
}

KeywordSpec th(std::string_view kw, RefKind ref, std::string_view meaning, std::string_view what) {
  KeywordSpec k = object(kw, meaning);
  k.name_rows = var_list();
  k.rows = id_list("objects", ref, what);
  return k;
}

}  // namespace

void add_starter_loads(std::vector<KeywordSpec>& out) {
  {
    KeywordSpec k = object("/GRNOD/NODE", "Node group listing node ids, up to 10 per line.");
    k.rows = id_list("nodes", RefKind::Node, "node identifier");
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/GRNOD/PART", "Node group of all nodes of the listed parts, up to 10 per line.");
    k.rows = id_list("parts", RefKind::Part, "part identifier");
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/FUNCT", "Tabulated function y(x); abscissa strictly increasing.");
    k.rows = line("point", {
        real_field("X", 0, Dimension::None, kAny, 0, "abscissa"),
        real_field("Y", 20, Dimension::None, kAny, 0, "ordinate"),
    });
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/BCS", "Fixed degrees of freedom of a node group.");
    k.lines.push_back(line("line 1", {
        text_field("Tra", 3, 3, "translations X Y Z fixed (1) or free (0), columns 4-6, e.g. 111"),
        text_field("rot", 7, 3, "rotations X Y Z fixed (1) or free (0), columns 8-10"),
        id_field("skew_id", 10, RefKind::Skew, false, "skew system (0 = global)"),
        id_field("grnod_id", 20, RefKind::Grnod, true, "node group"),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/IMPVEL", "Imposed velocity v(t) = Fscale_y * f(t / Ascale_x) on a node group.");
    k.lines.push_back(line("line 1", {
        id_field("fct_id", 0, RefKind::Funct, true, "velocity vs time function"),
        text_field("Dir", 10, 10, "direction X, Y, Z (translation) or XX, YY, ZZ (rotation)"),
        id_field("skew_id", 20, RefKind::Skew, false, "skew system"),
        id_field("sens_id", 30, RefKind::Sensor, false, "sensor"),
        id_field("grnod_id", 40, RefKind::Grnod, true, "node group"),
        int_field("frame_id", 50, 0, 0, 0, "frame (not supported, 0)", Dimension::Id),
        int_field("Icoor", 60, 0, 0, 0, "coordinate flag (0)"),
    }));
    k.lines.push_back(line("line 2", {
        real_field("Ascale_x", 0, Dimension::Time, kPositive, 1, "abscissa (time) scale"),
        zero_means_default(real_field("Fscale_y", 20, Dimension::Velocity, kAny, 1, "ordinate (velocity) scale")),
        real_field("Tstart", 40, Dimension::Time, kNonNegative, 0, "start time"),
        real_field("Tstop", 60, Dimension::Time, kNonNegative, 0, "stop time (0 = never)"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/INIVEL/TRA", "Initial translational velocity of a node group.");
    k.lines.push_back(line("line 1", {
        real_field("Vx", 0, Dimension::Velocity, kAny, 0, "X velocity"),
        real_field("Vy", 20, Dimension::Velocity, kAny, 0, "Y velocity"),
        real_field("Vz", 40, Dimension::Velocity, kAny, 0, "Z velocity"),
        id_field("grnod_id", 60, RefKind::Grnod, true, "node group"),
        id_field("skew_id", 70, RefKind::Skew, false, "skew system"),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/GRAV", "Gravity acceleration g(t) = Fscale_y * f(t / Ascale_x) on a node group.");
    k.lines.push_back(line("line 1", {
        id_field("fct_id", 0, RefKind::Funct, true, "acceleration vs time function"),
        text_field("Dir", 10, 10, "direction X, Y or Z"),
        id_field("skew_id", 20, RefKind::Skew, false, "skew system"),
        id_field("sens_id", 30, RefKind::Sensor, false, "sensor"),
        id_field("grnod_id", 40, RefKind::Grnod, true, "node group"),
    }));
    k.lines.push_back(line("line 2", {
        real_field("Ascale_x", 0, Dimension::Time, kPositive, 1, "abscissa (time) scale"),
        zero_means_default(real_field("Fscale_y", 20, Dimension::Acceleration, kAny, 1, "ordinate (acceleration) scale")),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/TH/NODE", "Nodal time history: variable lines, then node_id skew_id name.");
    k.name_rows = var_list();
    k.rows = line("node", {
        id_field("node_id", 0, RefKind::Node, true, "node"),
        id_field("skew_id", 10, RefKind::Skew, false, "skew system"),
        text_field("name", 20, 80, "output name"),
    });
    out.push_back(std::move(k));
  }
  out.push_back(th("/TH/PART", RefKind::Part,
                    "Part time history: IE, KE, HE (energies), XMOM, YMOM, ZMOM (momentum of the part's element nodes), "
                    "MASS (without added mass), XCG, YCG, ZCG (centre of gravity), AM (added mass), M (mass with it), "
                    "ER (deleted elements); DEF = IE KE XMOM YMOM ZMOM MASS HE AM.",
                    "part identifier"));
  out.push_back(th("/TH/SPRING", RefKind::Spring, "Spring element time history.", "spring element identifier"));
  out.push_back(th("/TH/INTER", RefKind::Inter, "Contact interface time history.", "interface identifier"));
  out.push_back(th("/TH/RBODY", RefKind::Rbody, "Rigid body time history.", "rigid body identifier"));
  out.push_back(th("/TH/RWALL", RefKind::Rwall, "Rigid wall time history.", "rigid wall identifier"));
}

}  // namespace hbm::deck::tables
