// SPDX-License-Identifier: GPL-3.0-or-later
// Keyword tables of parts, properties and materials: /PART, /PROP/TYPE1 (shell),
// /PROP/TYPE4 (1-DOF spring), /PROP/TYPE8 and /PROP/TYPE13 (6-DOF springs), /PROP/TYPE14
// (solid), /MAT/LAW1, /MAT/LAW2, /MAT/LAW34, /MAT/LAW36, /MAT/LAW42. Layouts: Radioss 2024 reference
// guide, block format; every numeric range here is enforced by the checks.
#include "field_builders.hpp"

namespace hbm::deck::tables {

namespace {

FieldSpec fct(std::string_view name, int col, std::string_view meaning) {
  return id_field(name, col, RefKind::Funct, false, meaning);
}

LineSpec density_line() {
  return line("density", {
      real_field("rho", 0, Dimension::Density, kPositive, 0, "initial density (rho_i)"),
      real_field("rho0", 20, Dimension::Density, kNonNegative, 0, "reference density for the equation of state (0 = rho)"),
  });
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
        int_field("Ipinch", 40, 0, 1, 0, "pinching DOF flag"),
        real_field("P_thick_fail", 60, Dimension::None, kUnit, 0,
                   "fraction of failed through-thickness points to delete the element"),
    }));
    k.lines.push_back(line("line 2", {
        real_field("hm", 0, Dimension::None, kUnit, 0,
                   "membrane hourglass coefficient (0: 0.01; 0.1 with Ishell 3)"),
        real_field("hf", 20, Dimension::None, kUnit, 0,
                   "out-of-plane hourglass coefficient (0: 0.01; 0.1 with Ishell 3)"),
        real_field("hr", 40, Dimension::None, kUnit, 0, "rotation hourglass coefficient (0: 0.01)"),
        real_field("dm", 60, Dimension::None, kNonNegative, 0, "membrane damping"),
        real_field("dn", 80, Dimension::None, kNonNegative, 0, "numerical damping"),
    }, true));
    k.lines.push_back(line("line 3", {
        int_field("N", 0, 0, 10, 0, "integration points through the thickness (0 = 5)", Dimension::Count),
        int_field("Istrain", 10, 0, 2, 0, "strain output flag (Radioss 2020 layout; blank in 2024)"),
        real_field("Thick", 20, Dimension::Length, kNonNegative, 0,
                   "shell thickness (0: each element needs its own or its part's thickness)"),
        real_field("Ashear", 40, Dimension::None, kNonNegative, 5.0 / 6.0, "shear factor (default 5/6)"),
        int_field("Ithick", 70, 0, 2, 0, "thickness change flag"),
        int_field("Iplas", 80, 0, 2, 0, "plane stress plasticity flag"),
        int_field("Ipos", 90, 0, 4, 0, "reference plane position (0 = mid-surface)"),
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
        zero_means_default(real_field("A", 40, Dimension::None, kAny, 1, "scale of the nonlinear stiffness function")),
        real_field("B", 60, Dimension::None, kAny, 0, "logarithmic rate effect scale"),
        zero_means_default(real_field("D", 80, Dimension::None, kAny, 1, "logarithmic rate effect scale")),
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
        zero_means_default(real_field("F", 0, Dimension::None, kAny, 1, "rate effect function scale")),
        zero_means_default(real_field("E", 20, Dimension::None, kAny, 1, "rate effect function scale")),
        zero_means_default(real_field("Ascale", 40, Dimension::Length, kAny, 1, "abscissa scale of fct_id1")),
        zero_means_default(real_field("Hscale", 60, Dimension::Velocity, kAny, 1, "abscissa scale of fct_id2")),
    }, true));
    out.push_back(std::move(k));
  }
  for (const bool beam : {false, true}) {
    KeywordSpec k = object(beam ? "/PROP/TYPE13" : "/PROP/TYPE8",
                           beam ? "Beam-type spring: 6 DOF (tension, 2 shears, torsion, 2 bendings) in the spring frame."
                                : "General spring: 6 independent DOF (X Y Z translations, X Y Z rotations).");
    if (beam) {
      k.lines.push_back(line("line 1", {
          real_field("Mass", 0, Dimension::Mass, kNonNegative, 0, "spring mass"),
          real_field("Inertia", 20, Dimension::Inertia, kNonNegative, 0, "spring inertia (<= 1e-20 reads as 1e-20, as in OpenRadioss)"),
          id_field("skew_id", 40, RefKind::Skew, false, "skew system"),
          id_field("sens_id", 50, RefKind::Sensor, false, "sensor"),
          int_field("Isflag", 60, 0, 2, 0, "sensor flag"),
          int_field("Ifail", 70, 0, 1, 0, "failure criteria flag"),
          int_field("Ileng", 80, 0, 1, 0, "input per unit length flag"),
          int_field("Ifail2", 90, 0, 3, 0, "failure model flag"),
      }));
    } else {
      k.lines.push_back(line("line 1", {
          real_field("Mass", 0, Dimension::Mass, kNonNegative, 0, "spring mass"),
          real_field("Inertia", 20, Dimension::Inertia, kNonNegative, 0, "spring inertia I (<= 1e-20 reads as 1e-20, as in OpenRadioss)"),
          id_field("skew_id", 40, RefKind::Skew, false, "skew system"),
          id_field("sens_id", 50, RefKind::Sensor, false, "sensor"),
          int_field("Isflag", 60, 0, 2, 0, "sensor flag"),
          int_field("Ifail", 70, 0, 1, 0, "failure criteria flag"),
          int_field("Ifail2", 80, 0, 3, 0, "failure model flag"),
          int_field("Iequil", 90, 0, 1, 0, "equilibrium flag"),
      }));
    }
    // Six blocks of three lines, one per DOF i = 1..6 (1-3 translations, 4-6 rotations).
    static constexpr std::string_view K[] = {"K1", "K2", "K3", "K4", "K5", "K6"};
    static constexpr std::string_view C[] = {"C1", "C2", "C3", "C4", "C5", "C6"};
    static constexpr std::string_view A[] = {"A1", "A2", "A3", "A4", "A5", "A6"};
    static constexpr std::string_view B[] = {"B1", "B2", "B3", "B4", "B5", "B6"};
    static constexpr std::string_view D[] = {"D1", "D2", "D3", "D4", "D5", "D6"};
    static constexpr std::string_view F1[] = {"fct_ID11", "fct_ID12", "fct_ID13", "fct_ID14", "fct_ID15", "fct_ID16"};
    static constexpr std::string_view H[] = {"H1", "H2", "H3", "H4", "H5", "H6"};
    static constexpr std::string_view F2[] = {"fct_ID21", "fct_ID22", "fct_ID23", "fct_ID24", "fct_ID25", "fct_ID26"};
    static constexpr std::string_view F3[] = {"fct_ID31", "fct_ID32", "fct_ID33", "fct_ID34", "fct_ID35", "fct_ID36"};
    static constexpr std::string_view F4[] = {"fct_ID41", "fct_ID42", "fct_ID43", "fct_ID44", "fct_ID45", "fct_ID46"};
    static constexpr std::string_view DMIN[] = {"dmin1", "dmin2", "dmin3", "dmin4", "dmin5", "dmin6"};
    static constexpr std::string_view DMAX[] = {"dmax1", "dmax2", "dmax3", "dmax4", "dmax5", "dmax6"};
    static constexpr std::string_view FF[] = {"F1", "F2", "F3", "F4", "F5", "F6"};
    static constexpr std::string_view EE[] = {"E1", "E2", "E3", "E4", "E5", "E6"};
    static constexpr std::string_view AS[] = {"Ascale1", "Ascale2", "Ascale3", "Ascale4", "Ascale5", "Ascale6"};
    static constexpr std::string_view HS[] = {"Hscale1", "Hscale2", "Hscale3", "Hscale4", "Hscale5", "Hscale6"};
    static constexpr std::string_view block_names[6][3] = {
        {"DOF 1 stiffness", "DOF 1 functions", "DOF 1 rate"}, {"DOF 2 stiffness", "DOF 2 functions", "DOF 2 rate"},
        {"DOF 3 stiffness", "DOF 3 functions", "DOF 3 rate"}, {"DOF 4 stiffness", "DOF 4 functions", "DOF 4 rate"},
        {"DOF 5 stiffness", "DOF 5 functions", "DOF 5 rate"}, {"DOF 6 stiffness", "DOF 6 functions", "DOF 6 rate"}};
    for (int i = 0; i < 6; ++i) {
      const bool rot = i >= 3;
      k.lines.push_back(line(block_names[i][0], {
          real_field(K[i], 0, rot ? Dimension::RotStiffness : Dimension::Stiffness, kNonNegative, 0, "linear stiffness"),
          real_field(C[i], 20, rot ? Dimension::RotDamping : Dimension::Damping, kNonNegative, 0, "linear damping"),
          zero_means_default(real_field(A[i], 40, Dimension::None, kAny, 1, "scale of the nonlinear stiffness function")),
          real_field(B[i], 60, Dimension::None, kAny, 0, "logarithmic rate effect scale"),
          zero_means_default(real_field(D[i], 80, Dimension::None, kAny, 1, "logarithmic rate effect scale")),
      }, true));
      k.lines.push_back(line(block_names[i][1], {
          fct(F1[i], 0, "force (moment) vs displacement (rotation) function"),
          int_field(H[i], 10, 0, 8, 0, "hardening flag (0 elastic)"),
          fct(F2[i], 20, "rate effect function"),
          fct(F3[i], 30, "unloading function"),
          fct(F4[i], 40, "damping function"),
          real_field(DMIN[i], 60, rot ? Dimension::Angle : Dimension::Length, kAny, 0, "failure limit in compression"),
          real_field(DMAX[i], 80, rot ? Dimension::Angle : Dimension::Length, kAny, 0, "failure limit in tension"),
      }, true));
      k.lines.push_back(line(block_names[i][2], {
          zero_means_default(real_field(FF[i], 0, Dimension::None, kAny, 1, "rate effect scale")),
          zero_means_default(real_field(EE[i], 20, Dimension::None, kAny, 1, "rate effect scale")),
          zero_means_default(real_field(AS[i], 40, rot ? Dimension::Angle : Dimension::Length, kAny, 1, "abscissa scale of the stiffness function")),
          zero_means_default(real_field(HS[i], 60, Dimension::Velocity, kAny, 1, "abscissa scale of the rate function")),
      }, true));
    }
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
        int_field("Itetra4", 60, 0, 3, 0, "4-node tetra formulation flag (0: constant strain; 3: average nodal pressure; 1, 2: not supported by hbm-solver)"),
        int_field("Iframe", 70, 0, 2, 0, "element frame flag"),
        real_field("dn", 80, Dimension::None, kNonNegative, 0, "numerical damping: Isolid 24's viscous hourglass coefficient (0 = 0.1)"),
    }));
    k.lines.push_back(line("line 2", {
        zero_means_default(real_field("qa", 0, Dimension::None, kNonNegative, 1.1, "quadratic bulk viscosity")),
        zero_means_default(real_field("qb", 20, Dimension::None, kNonNegative, 0.05, "linear bulk viscosity")),
        zero_means_default(real_field("h", 40, Dimension::None, kUnit, 0.1, "hourglass coefficient of Isolid 1, 2 (not used by 24: dn)")),
        real_field("lambda_v", 60, Dimension::None, kNonNegative, 0, "numerical viscosity lambda_v"),
        real_field("mu_v", 80, Dimension::None, kNonNegative, 0, "numerical viscosity mu_v"),
    }, true));
    k.lines.push_back(line("line 3", {
        real_field("dtmin", 0, Dimension::Time, kNonNegative, 0, "minimum time step"),
        int_field("Istrain", 20, 0, 2, 0, "strain output flag"),
        int_field("Ihkt", 30, 0, 2, 0, "tangent modulus estimation flag"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/MAT/LAW1", "Linear elastic material.");
    k.lines.push_back(density_line());
    k.lines.push_back(line("elasticity", {
        real_field("E", 0, Dimension::Stress, kPositive, 0, "Young's modulus"),
        poisson_field("nu", 20),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/MAT/LAW2",
                           "Johnson-Cook elasto-plastic material: sigma = (a + b eps_p^n)(1 + c ln(epsdot/EPS_DOT_0)).");
    k.lines.push_back(density_line());
    k.lines.push_back(line("elasticity", {
        real_field("E", 0, Dimension::Stress, kPositive, 0, "Young's modulus"),
        poisson_field("nu", 20),
        int_field("Iflag", 40, 0, 2, 0, "input flag (0 = a, b, n)"),
    }));
    k.lines.push_back(line("hardening", {
        real_field("a", 0, Dimension::Stress, kPositive, 0, "yield stress"),
        real_field("b", 20, Dimension::Stress, kNonNegative, 0, "hardening parameter"),
        zero_means_default(real_field("n", 40, Dimension::None, {0, 1, false, false}, 1, "hardening exponent")),
        real_field("EPS_p_max", 60, Dimension::Strain, kNonNegative, 0,
                   "plastic strain at element deletion (0 = none)"),
        real_field("SIG_max0", 80, Dimension::Stress, kNonNegative, 0, "maximum stress (0 = none)"),
    }));
    k.lines.push_back(line("strain rate", {
        real_field("c", 0, Dimension::None, kNonNegative, 0, "strain rate coefficient"),
        real_field("EPS_DOT_0", 20, Dimension::StrainRate, kNonNegative, 0, "reference strain rate"),
        int_field("ICC", 40, 0, 2, 0, "SIG_max0 and the rate term (0, 1 scaled by it; 2 not)"),
        int_field("Fsmooth", 50, 0, 1, 0, "strain rate smoothing flag (OpenRadioss filters by F_cut alone)"),
        real_field("F_cut", 60, Dimension::Frequency, kNonNegative, 0, "strain rate filter cutoff frequency"),
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
    // Layout of the Radioss reference guide (/MAT/LAW42 (OGDEN)): rho_i; nu, sigma_cut,
    // (blank), fct_IDblk, Fscale_blk, M, Iform; mu_1..mu_5; alpha_1..alpha_5; Prony terms when
    // M > 0 (not read: M is held to 0 by its range, as fct_IDblk and Iform).
    KeywordSpec k = object("/MAT/LAW42",
                           "Ogden hyperelastic incompressible material: W = sum mu_p / alpha_p (l1^a_p + "
                           "l2^a_p + l3^a_p - 3) (this library: shells, no Prony terms, no bulk function).");
    k.lines.push_back(density_line());
    k.lines.push_back(line("parameters", {
        zero_means_default(real_field("nu", 0, Dimension::None, {0, 0.5, false, true}, 0.495,
                                      "Poisson's ratio (0 = 0.495; shells follow incompressibility)")),
        zero_means_default(real_field("sigma_cut", 20, Dimension::Stress, kPositive, 1e30,
                                      "cut-off of the principal stresses in tension (0 = 1e30)")),
        int_field("fct_IDblk", 50, 0, 0, 0, "bulk function (this library: 0, none)", Dimension::Id),
        real_field("Fscale_blk", 60, Dimension::None, kAny, 0, "scale of the bulk function"),
        int_field("M", 80, 0, 0, 0, "number of Prony terms (this library: 0)", Dimension::Count),
        int_field("Iform", 90, 0, 0, 0, "shell incompressibility formulation (this library: 0)"),
    }));
    k.lines.push_back(line("mu", {
        real_field("mu1", 0, Dimension::Stress, kAny, 0, "Ogden modulus of pair 1"),
        real_field("mu2", 20, Dimension::Stress, kAny, 0, "Ogden modulus of pair 2"),
        real_field("mu3", 40, Dimension::Stress, kAny, 0, "Ogden modulus of pair 3"),
        real_field("mu4", 60, Dimension::Stress, kAny, 0, "Ogden modulus of pair 4"),
        real_field("mu5", 80, Dimension::Stress, kAny, 0, "Ogden modulus of pair 5"),
    }));
    k.lines.push_back(line("alpha", {
        real_field("alpha1", 0, Dimension::None, kAny, 0, "Ogden exponent of pair 1"),
        real_field("alpha2", 20, Dimension::None, kAny, 0, "Ogden exponent of pair 2"),
        real_field("alpha3", 40, Dimension::None, kAny, 0, "Ogden exponent of pair 3"),
        real_field("alpha4", 60, Dimension::None, kAny, 0, "Ogden exponent of pair 4"),
        real_field("alpha5", 80, Dimension::None, kAny, 0, "Ogden exponent of pair 5"),
    }));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = object("/MAT/LAW36",
                           "Tabulated elasto-plastic material: yield stress vs plastic strain curves "
                           "(this library reads up to 5 curves).");
    k.lines.push_back(density_line());
    k.lines.push_back(line("elasticity", {
        real_field("E", 0, Dimension::Stress, kPositive, 0, "Young's modulus"),
        poisson_field("nu", 20),
        real_field("EPS_p_max", 40, Dimension::Strain, kNonNegative, 0,
                   "plastic strain at failure (0 = none)"),
        real_field("EPS_t", 60, Dimension::Strain, kNonNegative, 0, "tensile strain for damage onset"),
        real_field("EPS_m", 80, Dimension::Strain, kNonNegative, 0, "tensile strain for deletion"),
    }));
    k.lines.push_back(line("curves", {
        int_field("N_funct", 0, 1, 5, 0, "number of yield curves (1..5)", Dimension::Count),
        int_field("Fsmooth", 10, 0, 1, 0, "strain rate smoothing flag"),
        real_field("Chard", 20, Dimension::None, kUnit, 0, "hardening coefficient (0 isotropic)"),
        real_field("F_cut", 40, Dimension::Frequency, kNonNegative, 0,
                   "strain rate filter cutoff frequency (0 = 10 kHz with two or more curves)"),
        real_field("EPS_f", 60, Dimension::Strain, kNonNegative, 0, "failure strain"),
        int_field("Vp", 90, 0, 2, 0, "strain rate choice flag (0, 2 equivalent strain rate; 1 plastic strain rate)"),
    }));
    k.lines.push_back(line("pressure", {
        fct("fct_IDp", 0, "yield scale factor vs pressure"),
        real_field("Fscale_p", 10, Dimension::Stress, kAny, 0, "scale of fct_IDp"),
        fct("fct_IDE", 30, "Young's modulus scale vs plastic strain"),
        real_field("Einf", 40, Dimension::Stress, kNonNegative, 0, "saturated Young's modulus"),
        real_field("CE", 60, Dimension::None, kNonNegative, 0, "Young's modulus evolution parameter"),
    }, true));
    k.lines.push_back(line("yield curves", {
        fct("fct_ID1", 0, "yield curve 1"), fct("fct_ID2", 10, "yield curve 2"),
        fct("fct_ID3", 20, "yield curve 3"), fct("fct_ID4", 30, "yield curve 4"),
        fct("fct_ID5", 40, "yield curve 5"),
    }));
    k.lines.push_back(line("curve scales", {
        zero_means_default(real_field("Fscale1", 0, Dimension::Stress, kAny, 1, "scale of yield curve 1")),
        zero_means_default(real_field("Fscale2", 20, Dimension::Stress, kAny, 1, "scale of yield curve 2")),
        zero_means_default(real_field("Fscale3", 40, Dimension::Stress, kAny, 1, "scale of yield curve 3")),
        zero_means_default(real_field("Fscale4", 60, Dimension::Stress, kAny, 1, "scale of yield curve 4")),
        zero_means_default(real_field("Fscale5", 80, Dimension::Stress, kAny, 1, "scale of yield curve 5")),
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
