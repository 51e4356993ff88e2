// SPDX-License-Identifier: GPL-3.0-or-later
// Injury risk functions (see risk_functions.hpp for coefficients and sources).
#include "hbm/corridors/risk_functions.hpp"

#include <cmath>

namespace hbm::corridors {

double standard_normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

double chest_deflection_ais3_risk_laituri2005(double d, double age) {
  if (d <= 0.0) d = 0.0;
  return 1.0 / (1.0 + std::exp(12.597 - 0.05861 * age - 1.568 * std::pow(d, 0.4612)));
}

double hic15_ais3_risk_nhtsa(double hic15) {
  if (hic15 <= 0.0) return 0.0;
  return standard_normal_cdf((std::log(hic15) - 7.45231) / 0.73998);
}

double nij_ais3_risk_nhtsa(double nij) { return 1.0 / (1.0 + std::exp(3.2269 - 1.9688 * nij)); }

}  // namespace hbm::corridors
