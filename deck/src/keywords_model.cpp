// SPDX-License-Identifier: GPL-3.0-or-later
// Keyword tables of parts, properties and materials: /PART, /PROP/TYPE1 (shell),
// /PROP/TYPE4 (1-DOF spring), /PROP/TYPE8 and /PROP/TYPE13 (6-DOF springs), /PROP/TYPE14
// (solid), /MAT/LAW1, /MAT/LAW2, /MAT/LAW34, /MAT/LAW36. Layouts: Radioss 2024 reference
// guide, block format; every numeric range here is enforced by the checks.
#include "field_builders.hpp"

namespace hbm::deck::tables {

namespace {

KeywordSpec object(std::string_view kw, std::string_view meaning) {
  KeywordSpec k;
  k.keyword = kw;
  k.section = Section::Starter;
  k.id = IdKind::Object;
  k.has_title = true;
  k.meaning = meaning;
  return k;
}

FieldSpec fct(std::string_view name, int col, std::string_view meaning) {
  return id_field(name, col, RefKind::Funct, false, meaning);
}

LineSpec density_line() {
  return line("density", {real_field("rho", 0, Dimension::Density, kPositive, 0, "initial density")});
}

}  // namespace

void add_starter_model(std::vector<KeywordSpec>& out) {
  {
    KeywordSpec k = object("/PART", "Part: ties a property and a material to elements.");
    k.lines.push_back(line("line 1", {
        id_field("prop_id", 0, RefKind::Prop, true, "property identifier"),
        id_field("mat_id", 10, RefKind::Mat, false, "material identifier (0 allowed for spring parts only)"),
        int_field("subset_id", 20, 0, kNoLimit, 0, "subset identifier (not used)", Dimension::Id),
        real_field("thick", 30, Dimension::Length, kNonNegative, 0,
                   "shell thickness overriding the property (0 = property's)"),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/PROP/TYPE1", "Shell property (Belytschko-type 4-node / 3-node shell).");
    k.lines.push_back(line("line 1", {
        int_field("Ishell", 0, 0, 24, 0, "shell formulation flag"),
        int_field("Ismstr", 10, 0, 11, 0, "small strain flag"),
        int_field("Ish3n", 20, 0, 31, 0, "3-node shell formulation flag"),
        int_field("Idrill", 30, 0, 2, 0, "drilling DOF flag"),
        real_field("P_thick_fail", 40, Dimension::None, kUnit, 0,
                   "fraction of failed layers to delete the element"),
    }));
    k.lines.push_back(line("line 2", {
        real_field("hm", 0, Dimension::None, kNonNegative, 0.01, "membrane hourglass coefficient"),
        real_field("hf", 20, Dimension::None, kNonNegative, 0.01, "out-of-plane hourglass coefficient"),
        real_field("hr", 40, Dimension::None, kNonNegative, 0.01, "rotation hourglass coefficient"),
        real_field("dm", 60, Dimension::None, kNonNegative, 0, "membrane damping"),
        real_field("dn", 80, Dimension::None, kNonNegative, 0, "numerical damping"),
    }, true));
    k.lines.push_back(line("line 3", {
        int_field("N", 0, 0, 10, 0, "integration points through the thickness (0 = 5)", Dimension::Count),
        int_field("Istrain", 10, 0, 2, 0, "strain output flag"),
        real_field("Thick", 20, Dimension::Length, kPositive, 0, "shell thickness"),
        real_field("Ashear", 40, Dimension::None, kNonNegative, 0, "shear factor (0 = 5/6)"),
        int_field("Ithick", 60, 0, 2, 0, "thickness change flag"),
        int_field("Iplas", 70, 0, 2, 0, "plane stress plasticity flag"),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/PROP/TYPE4", "Spring property with one translational DOF along n1-n2.");
    k.lines.push_back(line("line 1", {
        real_field("Mass", 0, Dimension::Mass, kNonNegative, 0, "spring mass (split to both nodes)"),
        id_field("sens_id", 20, RefKind::Sensor, false, "sensor activating the spring"),
        int_field("Isflag", 30, 0, 2, 0, "sensor flag"),
        int_field("Ileng", 40, 0, 1, 0, "input per unit length flag"),
    }));
    k.lines.push_back(line("line 2", {
        real_field("K", 0, Dimension::Stiffness, kNonNegative, 0, "linear stiffness"),
        real_field("C", 20, Dimension::Damping, kNonNegative, 0, "linear damping"),
        real_field("A", 40, Dimension::None, kAny, 1, "scale of the nonlinear stiffness function"),
        real_field("B", 60, Dimension::None, kAny, 0, "logarithmic rate effect scale"),
        real_field("D", 80, Dimension::None, kAny, 1, "logarithmic rate effect scale"),
    }));
    k.lines.push_back(line("line 3", {
        fct("fct_id1", 0, "force vs displacement function f(delta)"),
        int_field("H", 10, 0, 8, 0, "hardening flag (0 elastic)"),
        fct("fct_id2", 20, "rate effect function g(delta_dot)"),
        fct("fct_id3", 30, "unloading function"),
        fct("fct_id4", 40, "damping force function"),
        real_field("dmin", 60, Dimension::Length, kAny, 0, "failure displacement in compression"),
        real_field("dmax", 80, Dimension::Length, kAny, 0, "failure displacement in tension"),
    }, true));
    k.lines.push_back(line("line 4", {
        real_field("F", 0, Dimension::None, kAny, 1, "rate effect function scale"),
        real_field("E", 20, Dimension::None, kAny, 0, "rate effect function scale"),
        real_field("Ascale", 40, Dimension::Length, kAny, 1, "abscissa scale of fct_id1"),
        real_field("Hscale", 60, Dimension::Velocity, kAny, 1, "abscissa scale of fct_id2"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/PROP/TYPE14", "Solid property (8-node brick, 4-node tetra).");
    k.lines.push_back(line("line 1", {
        int_field("Isolid", 0, 0, 24, 0, "solid formulation flag (0 = 1: 1-point, viscous hourglass)"),
        int_field("Ismstr", 10, 0, 12, 0, "small strain flag"),
        int_field("Iale", 20, 0, 0, 0, "ALE flag (Lagrange only)"),
        int_field("Icpre", 30, 0, 3, 0, "constant pressure flag"),
        int_field("Itetra10", 40, 0, 3, 0, "10-node tetra formulation flag"),
        int_field("Inpts", 50, 0, 333, 0, "number of integration points", Dimension::Count),
        int_field("Itetra4", 60, 0, 3, 0, "4-node tetra formulation flag"),
        int_field("Iframe", 70, 0, 2, 0, "element frame flag"),
        real_field("dn", 80, Dimension::None, kNonNegative, 0, "numerical damping"),
    }));
    k.lines.push_back(line("line 2", {
        real_field("qa", 0, Dimension::None, kNonNegative, 1.1, "quadratic bulk viscosity"),
        real_field("qb", 20, Dimension::None, kNonNegative, 0.05, "linear bulk viscosity"),
        real_field("h", 40, Dimension::None, kUnit, 0.1, "hourglass coefficient"),
    }, true));
    k.lines.push_back(line("line 3", {
        real_field("dtmin", 0, Dimension::Time, kNonNegative, 0, "minimum time step"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/MAT/LAW1", "Linear elastic material.");
    k.lines.push_back(density_line());
    k.lines.push_back(line("elasticity", {
        real_field("E", 0, Dimension::Stress, kPositive, 0, "Young's modulus"),
        real_field("nu", 20, Dimension::None, kPoisson, 0, "Poisson's ratio"),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/MAT/LAW2",
                           "Johnson-Cook elasto-plastic material: sigma = (a + b eps_p^n)(1 + c ln(epsdot/EPS_DOT_0)).");
    k.lines.push_back(density_line());
    k.lines.push_back(line("elasticity", {
        real_field("E", 0, Dimension::Stress, kPositive, 0, "Young's modulus"),
        real_field("nu", 20, Dimension::None, kPoisson, 0, "Poisson's ratio"),
        int_field("Iflag", 40, 0, 2, 0, "input flag (0 = a, b, n)"),
    }));
    k.lines.push_back(line("hardening", {
        real_field("a", 0, Dimension::Stress, kPositive, 0, "yield stress"),
        real_field("b", 20, Dimension::Stress, kNonNegative, 0, "hardening parameter"),
        real_field("n", 40, Dimension::None, {0, 1, false, false}, 1, "hardening exponent"),
        real_field("EPS_p_max", 60, Dimension::Strain, kNonNegative, 0,
                   "plastic strain at element deletion (0 = none)"),
        real_field("SIG_max0", 80, Dimension::Stress, kNonNegative, 0, "maximum stress (0 = none)"),
    }));
    k.lines.push_back(line("strain rate", {
        real_field("c", 0, Dimension::None, kNonNegative, 0, "strain rate coefficient"),
        real_field("EPS_DOT_0", 20, Dimension::StrainRate, kNonNegative, 0, "reference strain rate"),
        int_field("ICC", 40, 0, 2, 0, "strain rate computation flag"),
        int_field("Fsmooth", 50, 0, 1, 0, "strain rate smoothing flag"),
        real_field("F_cut", 60, Dimension::Frequency, kNonNegative, 0, "strain rate cutoff frequency"),
    }, true));
    k.lines.push_back(line("temperature", {
        real_field("m", 0, Dimension::None, kNonNegative, 0, "temperature exponent"),
        real_field("T_melt", 20, Dimension::Temperature, kNonNegative, 0, "melting temperature"),
        real_field("rho0Cp", 40, Dimension::None, kNonNegative, 0, "specific heat per volume"),
        real_field("T_r", 60, Dimension::Temperature, kNonNegative, 298, "room temperature"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/MAT/LAW34",
                           "Boltzmann viscoelastic solid: G(t) = Ginf + (G0 - Ginf) exp(-beta t), bulk K.");
    k.lines.push_back(density_line());
    k.lines.push_back(line("bulk", {real_field("K", 0, Dimension::Stress, kPositive, 0, "bulk modulus")}));
    k.lines.push_back(line("shear", {
        real_field("G0", 0, Dimension::Stress, kPositive, 0, "short-time shear modulus"),
        real_field("Ginf", 20, Dimension::Stress, kNonNegative, 0, "long-time shear modulus"),
        real_field("beta", 40, Dimension::Frequency, kNonNegative, 0, "decay constant"),
    }));
    k.lines.push_back(line("foam", {
        real_field("P0", 0, Dimension::Stress, kNonNegative, 0, "initial air pressure (0 for tissue)"),
        real_field("Phi", 20, Dimension::None, kUnit, 0, "foam to polymer density ratio"),
        real_field("Gamma0", 40, Dimension::Strain, kAny, 0, "initial volumetric strain"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/MAT/LAW36",
                           "Tabulated elasto-plastic material: yield stress vs plastic strain curves "
                           "(this library reads up to 5 curves).");
    k.lines.push_back(density_line());
    k.lines.push_back(line("elasticity", {
        real_field("E", 0, Dimension::Stress, kPositive, 0, "Young's modulus"),
        real_field("nu", 20, Dimension::None, kPoisson, 0, "Poisson's ratio"),
        real_field("EPS_p_max", 40, Dimension::Strain, kNonNegative, 0,
                   "plastic strain at failure (0 = none)"),
        real_field("EPS_t", 60, Dimension::Strain, kNonNegative, 0, "tensile strain for damage onset"),
        real_field("EPS_m", 80, Dimension::Strain, kNonNegative, 0, "tensile strain for deletion"),
    }));
    k.lines.push_back(line("curves", {
        int_field("N_funct", 0, 1, 5, 0, "number of yield curves (1..5)", Dimension::Count),
        int_field("Fsmooth", 10, 0, 1, 0, "strain rate smoothing flag"),
        real_field("Chard", 20, Dimension::None, kUnit, 0, "hardening coefficient (0 isotropic)"),
        real_field("F_cut", 40, Dimension::Frequency, kNonNegative, 0, "strain rate cutoff frequency"),
        real_field("EPS_f", 60, Dimension::Strain, kNonNegative, 0, "failure strain"),
        int_field("Vp", 80, 0, 2, 0, "strain rate choice flag"),
    }));
    k.lines.push_back(line("pressure", {
        fct("fct_IDp", 0, "yield scale factor vs pressure"),
        real_field("Fscale_p", 20, Dimension::Stress, kAny, 0, "scale of fct_IDp"),
        fct("fct_IDE", 40, "Young's modulus scale vs plastic strain"),
        real_field("Einf", 60, Dimension::Stress, kNonNegative, 0, "saturated Young's modulus"),
        real_field("CE", 80, Dimension::None, kNonNegative, 0, "Young's modulus evolution parameter"),
    }, true));
    k.lines.push_back(line("yield curves", {
        fct("fct_ID1", 0, "yield curve 1"), fct("fct_ID2", 10, "yield curve 2"),
        fct("fct_ID3", 20, "yield curve 3"), fct("fct_ID4", 30, "yield curve 4"),
        fct("fct_ID5", 40, "yield curve 5"),
    }));
    k.lines.push_back(line("curve scales", {
        real_field("Fscale1", 0, Dimension::Stress, kAny, 1, "scale of yield curve 1"),
        real_field("Fscale2", 20, Dimension::Stress, kAny, 1, "scale of yield curve 2"),
        real_field("Fscale3", 40, Dimension::Stress, kAny, 1, "scale of yield curve 3"),
        real_field("Fscale4", 60, Dimension::Stress, kAny, 1, "scale of yield curve 4"),
        real_field("Fscale5", 80, Dimension::Stress, kAny, 1, "scale of yield curve 5"),
    }, true));
    k.lines.push_back(line("curve rates", {
        real_field("EPS_dot1", 0, Dimension::StrainRate, kNonNegative, 0, "strain rate of curve 1"),
        real_field("EPS_dot2", 20, Dimension::StrainRate, kNonNegative, 0, "strain rate of curve 2"),
        real_field("EPS_dot3", 40, Dimension::StrainRate, kNonNegative, 0, "strain rate of curve 3"),
        real_field("EPS_dot4", 60, Dimension::StrainRate, kNonNegative, 0, "strain rate of curve 4"),
        real_field("EPS_dot5", 80, Dimension::StrainRate, kNonNegative, 0, "strain rate of curve 5"),
    }, true));
    out.push_back(std::move(k));
  }
}

}  // namespace hbm::deck::tables
