// SPDX-License-Identifier: GPL-3.0-or-later
// Rating of cross-plot (force-deflection) corridors, whose loops have no time base that the
// model and the test share. Two parameterisations turn both curves into signals on one
// common uniform abscissa, which the time-history ratings (ISO/TS 18571, CORA) then take:
//  - "loading" (default): the loading branch of each curve (points up to the largest
//    deflection, deflection strictly increasing) as force over deflection, on a uniform
//    deflection grid from the later of the two curve starts to the reference's largest
//    deflection. Where the model did not deflect that far its force counts as 0, so a
//    model that is too stiff is penalised over the deflection it never reached.
//  - "arc_length": the whole loop (loading and unloading) of each curve, parameterised by
//    the fraction of its own arc length in coordinates normalised by the reference's
//    largest deflection and force; the force at equal arc-length fractions is compared.
#pragma once

#include <string>
#include <vector>

#include "hbm/corridors/corridor.hpp"

namespace hbm::corridors {

struct ParameterisedCurves {
  std::vector<double> abscissa;  ///< deflection (loading) or arc-length fraction (arc_length)
  std::vector<double> reference, model;
  double reference_reach = 0.0;  ///< largest deflection of the reference curve
  double model_reach = 0.0;      ///< largest deflection of the model curve
};

/// reference: the test mean (or corridor mid-line) in traversal order; model: the model
/// curve in time order. n: number of grid points (>= 10).
ParameterisedCurves parameterise_loading(const Polyline& reference, const Polyline& model,
                                         std::size_t n);

ParameterisedCurves parameterise_arc_length(const Polyline& reference, const Polyline& model,
                                            std::size_t n);

}  // namespace hbm::corridors
