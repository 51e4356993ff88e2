// SPDX-License-Identifier: GPL-3.0-or-later
// The brick kernel's vector lane helpers (solid/lane_vector_ops.hpp) against the libm
// functions they stand for: sqrt_lanes is IEEE square root (correctly rounded: the same
// bits as std::sqrt), cbrt_lanes a faithful cube root within 1 ulp of std::cbrt, and
// the same bits as glibc's (whose algorithm it follows) where glibc is the libm; special
// values (0, subnormal, infinity, NaN, negative) as std::cbrt. Rows of 1, 5 and 32
// lanes (remainder and full vectors).
#include "core/lane_vector_ops.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace hbm::solver::lanes {
namespace {

std::int64_t ulp_distance(double a, double b) {
  const auto ia = std::bit_cast<std::int64_t>(a), ib = std::bit_cast<std::int64_t>(b);
  return ia > ib ? ia - ib : ib - ia;
}

// Positive values spread over 2^-60 .. 2^60 (element volumes squared and more).
std::vector<double> samples(std::size_t n, unsigned seed) {
  std::mt19937_64 r(seed);
  std::uniform_real_distribution<double> mant(1.0, 2.0), expo(-60.0, 60.0);
  std::vector<double> x(n);
  for (double& v : x) v = mant(r) * std::exp2(std::floor(expo(r)));
  return x;
}

TEST(SolidLaneVectorOps, SqrtLanesIsIeeeSquareRoot) {
  for (const std::size_t n : {std::size_t{1}, std::size_t{5}, std::size_t{32}}) {
    for (unsigned seed = 1; seed <= 2000; ++seed) {
      std::vector<double> a = samples(n, seed);
      const std::vector<double> x = a;
      sqrt_lanes(n, a.data());
      for (std::size_t l = 0; l < n; ++l) ASSERT_EQ(std::bit_cast<std::uint64_t>(a[l]),
                                                    std::bit_cast<std::uint64_t>(std::sqrt(x[l])))
          << "x = " << x[l];
    }
  }
}

TEST(SolidLaneVectorOps, CbrtLanesWithinOneUlpOfLibm) {
  std::size_t total = 0, same_bits = 0;
  std::int64_t worst = 0;
  for (const std::size_t n : {std::size_t{1}, std::size_t{5}, std::size_t{32}}) {
    for (unsigned seed = 1; seed <= 20000; ++seed) {
      const std::vector<double> x = samples(n, seed);
      std::vector<double> y(n);
      cbrt_lanes(n, x.data(), y.data());
      for (std::size_t l = 0; l < n; ++l) {
        const double ref = std::cbrt(x[l]);
        const std::int64_t d = ulp_distance(y[l], ref);
        worst = std::max(worst, d);
        ASSERT_LE(d, 1) << "x = " << x[l] << ": " << y[l] << " against " << ref;
        ++total;
        same_bits += d == 0 ? 1 : 0;
      }
    }
  }
#ifdef __GLIBC__
  // glibc's algorithm, no fused multiply-adds: the same bits.
  EXPECT_EQ(same_bits, total) << "largest difference " << worst << " ulp";
#endif
}

TEST(SolidLaneVectorOps, CbrtLanesExactCubesAndSpecialValues) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> x = {8.0, 27.0, 1.0, 0.125, 1e6, 0.0, DBL_TRUE_MIN, 1e-310, DBL_MIN, DBL_MAX, inf,
                                 -8.0, std::numeric_limits<double>::quiet_NaN()};
  std::vector<double> y(x.size());
  cbrt_lanes(x.size(), x.data(), y.data());
  // Cubes: the cube root to 1 ulp (glibc's cbrt is faithful, not correctly rounded:
  // it gives 3 + 1 ulp for 27 and 0.5 - 1 ulp for 0.125).
  const double root[5] = {2.0, 3.0, 1.0, 0.5, 100.0};
  for (std::size_t l = 0; l < 5; ++l) EXPECT_LE(ulp_distance(y[l], root[l]), 1) << "x = " << x[l];
  for (std::size_t l = 5; l + 1 < x.size(); ++l)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(y[l]), std::bit_cast<std::uint64_t>(std::cbrt(x[l]))) << "x = " << x[l];
  EXPECT_TRUE(std::isnan(y.back()));
}

}  // namespace
}  // namespace hbm::solver::lanes
