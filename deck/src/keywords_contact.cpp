// SPDX-License-Identifier: GPL-3.0-or-later
// Keyword tables of rigid bodies, surfaces, contact interfaces and rigid walls: /RBODY,
// /SURF/PART, /SURF/SEG, /INTER/TYPE2 (tied), /INTER/TYPE7 (penalty node-to-surface),
// /RWALL/PLANE. Layouts: Radioss 2024 reference guide. Options that would add lines
// conditionally (thermal contact, friction models, curved surfaces, moving walls) are
// restricted by their ranges to the value that adds none, so every card has a fixed
// line count; the ranges say which.
#include "field_builders.hpp"

namespace hbm::deck::tables {

void add_starter_contact(std::vector<KeywordSpec>& out) {
  {
    KeywordSpec k = object("/RBODY", "Rigid body: main node at the centre of mass, secondary node group.");
    k.lines.push_back(line("line 1", {
        id_field("node_id", 0, RefKind::Node, true, "main node (moved to the centre of mass when ICoG = 1)"),
        id_field("sens_id", 10, RefKind::Sensor, false, "sensor"),
        id_field("skew_id", 20, RefKind::Skew, false, "skew system of the inertia"),
        int_field("Ispher", 30, 0, 2, 0, "inertia flag (1 = spherical: Jxx used for all axes)"),
        real_field("Mass", 40, Dimension::Mass, kNonNegative, 0, "added mass on the main node"),
        id_field("grnod_id", 60, RefKind::Grnod, true, "secondary node group (grnd_ID)"),
        int_field("Ikrem", 70, 0, 1, 0, "rigid wall deactivation flag"),
        int_field("ICoG", 80, 0, 4, 0, "centre of gravity computation flag"),
        id_field("surf_id", 90, RefKind::Surf, false, "envelope surface"),
    }));
    k.lines.push_back(line("inertia", {
        real_field("Jxx", 0, Dimension::Inertia, kNonNegative, 0, "added inertia XX"),
        real_field("Jyy", 20, Dimension::Inertia, kNonNegative, 0, "added inertia YY"),
        real_field("Jzz", 40, Dimension::Inertia, kNonNegative, 0, "added inertia ZZ"),
    }, true));
    k.lines.push_back(line("products of inertia", {
        real_field("Jxy", 0, Dimension::Inertia, kAny, 0, "added inertia XY"),
        real_field("Jyz", 20, Dimension::Inertia, kAny, 0, "added inertia YZ"),
        real_field("Jxz", 40, Dimension::Inertia, kAny, 0, "added inertia XZ"),
    }, true));
    k.lines.push_back(line("options", {
        int_field("Ioptoff", 0, -1, 1, 0, "domain decomposition flag"),
        int_field("Iexpams", 10, 0, 2, 0, "mass scaling of the secondary nodes flag"),
        int_field("Ifail", 20, 0, 0, 0, "failure flag (0: no failure, no extra line)"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/SURF/PART", "Surface of the listed parts' shells and solid outer faces, up to 10 parts per line.");
    std::vector<FieldSpec> f;
    for (int i = 0; i < 10; ++i) f.push_back(id_field(kIdNames[i], 10 * i, RefKind::Part, false, "part identifier"));
    k.rows = line("parts", std::move(f));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/SURF/SEG", "Surface of explicit segments (n4 blank or 0 for a triangle).");
    k.rows = line("segment", {
        int_field("seg_id", 0, 0, kNoLimit, 0, "segment identifier (optional)", Dimension::Id),
        id_field("n1", 10, RefKind::Node, true, "node 1"),
        id_field("n2", 20, RefKind::Node, true, "node 2"),
        id_field("n3", 30, RefKind::Node, true, "node 3"),
        id_field("n4", 40, RefKind::Node, false, "node 4 (blank for a triangle)"),
    });
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/INTER/TYPE2", "Tied contact: secondary nodes tied to the main surface.");
    k.lines.push_back(line("line 1", {
        id_field("grnod_id", 0, RefKind::Grnod, true, "secondary node group (grnd_IDs)"),
        id_field("surf_id", 10, RefKind::Surf, true, "main surface (surf_IDm)"),
        int_field("Ignore", 20, 0, 3, 0, "flag to ignore secondary nodes without a main segment"),
        int_field("Spotflag", 30, 0, 22, 0, "formulation flag (0 = default)"),
        int_field("Level", 40, 0, 1, 0, "hierarchy level"),
        int_field("Isearch", 50, 0, 2, 0, "search algorithm flag"),
        int_field("Idel2", 60, 0, 2, 0, "node deletion flag"),
        real_field("dsearch", 80, Dimension::Length, kNonNegative, 0, "search distance (0 = automatic)"),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/INTER/TYPE7",
                           "Penalty contact of secondary nodes on a main surface (Coulomb friction).");
    k.lines.push_back(line("line 1", {
        id_field("grnod_id", 0, RefKind::Grnod, true, "secondary node group (grnd_IDs)"),
        id_field("surf_id", 10, RefKind::Surf, true, "main surface (surf_IDm)"),
        int_field("Istf", 20, 0, 5, 0, "stiffness definition flag (0: Stfac is a scale factor)"),
        int_field("Ithe", 30, 0, 0, 0, "heat transfer flag (0 only)"),
        int_field("Igap", 40, 0, 3, 0, "gap flag (0: constant gap Gapmin)"),
        int_field("Ibag", 60, 0, 1, 0, "airbag vent closure flag"),
        int_field("Idel", 70, -2, 2, 0, "node and segment deletion flag"),
        int_field("Icurv", 80, 0, 0, 0, "curvature flag (0 only)"),
        int_field("Iadm", 90, 0, 2, 0, "adaptive meshing flag"),
    }));
    k.lines.push_back(line("gap", {
        real_field("Fscalegap", 0, Dimension::None, kNonNegative, 0, "gap scale factor (Igap >= 2; 0 = 1)"),
        real_field("Gapmax", 20, Dimension::Length, kNonNegative, 0, "maximum gap (Igap >= 2; 0 = none)"),
        real_field("Fpenmax", 40, Dimension::None, kUnit, 0, "maximum penetration fraction (0 = none)"),
        int_field("ITIED", 60, 0, 2, 0, "tied contact flag"),
    }));
    k.lines.push_back(line("stiffness limits", {
        real_field("Stmin", 0, Dimension::Stiffness, kNonNegative, 0, "minimum stiffness (Istf 2-5)"),
        real_field("Stmax", 20, Dimension::Stiffness, kNonNegative, 0, "maximum stiffness (Istf 2-5; 0 = none)"),
        real_field("mesh_size", 40, Dimension::None, kNonNegative, 0, "%mesh_size: gap as fraction of mesh size"),
        real_field("dtmin", 60, Dimension::Time, kNonNegative, 0, "minimum interface time step"),
        int_field("Irem_gap", 80, 0, 2, 0, "deactivate secondary nodes if element size < gap"),
        int_field("Irem_i2", 90, 0, 1, 0, "deactivate pairs already tied by TYPE2"),
    }));
    k.lines.push_back(line("contact", {
        zero_means_default(real_field("Stfac", 0, Dimension::None, kNonNegative, 1, "stiffness scale factor (Istf = 0) or stiffness")),
        real_field("Fric", 20, Dimension::None, kNonNegative, 0, "Coulomb friction coefficient"),
        real_field("Gapmin", 40, Dimension::Length, kNonNegative, 0, "minimum gap"),
        real_field("Tstart", 60, Dimension::Time, kNonNegative, 0, "start time"),
        real_field("Tstop", 80, Dimension::Time, kNonNegative, 0, "stop time (0 = never)"),
    }));
    k.lines.push_back(line("damping", {
        text_field("IBC", 7, 3, "boundary condition flags X Y Z of deactivated nodes, columns 8-10"),
        int_field("Inacti", 30, 0, 6, 0, "initial penetration treatment flag"),
        zero_means_default(real_field("VISs", 40, Dimension::None, kNonNegative, 0.05, "critical damping coefficient on stiffness")),
        real_field("VISF", 60, Dimension::None, kNonNegative, 1, "critical damping coefficient of the viscous friction (Iform 1; 0 = 1)"),
        real_field("Bumult", 80, Dimension::None, kNonNegative, 0.2, "sorting factor"),
    }));
    k.lines.push_back(line("friction", {
        int_field("Ifric", 0, 0, 0, 0, "friction formulation (0 = Coulomb only)"),
        int_field("Ifiltr", 10, 0, 3, 0, "friction filtering flag"),
        real_field("Xfreq", 20, Dimension::None, kNonNegative, 0, "filtering coefficient"),
        int_field("Iform", 40, 0, 2, 0, "friction penalty formulation: 0, 1 viscous (default), 2 incremental (stiffness)"),
        id_field("sens_id", 50, RefKind::Sensor, false, "sensor"),
        id_field("fct_IDF", 60, RefKind::Funct, false, "friction scale vs temperature function"),
        real_field("AscaleF", 70, Dimension::None, kAny, 1, "abscissa scale of fct_IDF"),
        int_field("fric_id", 90, 0, 0, 0, "friction model id (0: none)", Dimension::Id),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/RWALL/PLANE",
                           "Infinite plane rigid wall with normal M->M1: fixed through M (node_id = 0) or moving with node_id, given Mass and initial velocity.");
    k.lines.push_back(line("line 1", {
        id_field("node_id", 0, RefKind::Node, false, "wall node (0: fixed wall through M; else a moving wall at this node)"),
        int_field("Slide", 10, 0, 2, 0, "0 sliding, 1 tied, 2 sliding with friction"),
        id_field("grnod_id1", 20, RefKind::Grnod, false, "node group added to the secondary nodes"),
        id_field("grnod_id2", 30, RefKind::Grnod, false, "node group removed from the secondary nodes"),
    }));
    k.lines.push_back(line("search", {
        real_field("Dsearch", 0, Dimension::Length, kNonNegative, 0, "secondary nodes on the free side within this distance at t = 0 (0 = none by distance)"),
        real_field("fric", 20, Dimension::None, kNonNegative, 0, "friction coefficient (Slide = 2)"),
        real_field("Diameter", 40, Dimension::Length, kNonNegative, 0, "unused for a plane"),
        real_field("ffac", 60, Dimension::None, kNonNegative, 0, "friction filtering factor"),
        int_field("ifq", 80, 0, 3, 0, "friction filtering flag"),
    }));
    // Radioss reads this line as XM YM ZM when node_id = 0 and as Mass VX0 VY0 VZ0 when
    // node_id != 0 (same columns); the field names are those of the fixed wall.
    k.lines.push_back(line("point M (node_id = 0) or Mass VX0 VY0 VZ0 (node_id != 0)", {
        real_field("XM", 0, Dimension::None, kAny, 0, "X of point M on the wall; moving wall: its Mass"),
        real_field("YM", 20, Dimension::None, kAny, 0, "Y of point M; moving wall: initial velocity VX0"),
        real_field("ZM", 40, Dimension::None, kAny, 0, "Z of point M; moving wall: initial velocity VY0"),
        real_field("VZ0", 60, Dimension::Velocity, kAny, 0, "moving wall: initial velocity VZ0 (blank for a fixed wall)"),
    }));
    k.lines.push_back(line("point M1", {
        real_field("XM1", 0, Dimension::Length, kAny, 0, "X of M1: normal M->M1 points to the free side"),
        real_field("YM1", 20, Dimension::Length, kAny, 0, "Y of M1"),
        real_field("ZM1", 40, Dimension::Length, kAny, 0, "Z of M1"),
    }));
    out.push_back(std::move(k));
  }
}

}  // namespace hbm::deck::tables
