// SPDX-License-Identifier: GPL-3.0-or-later
// /FUNCT evaluation: exact values of a piecewise linear function inside the range, the
// documented linear extension outside it, and the hinted evaluation used for time
// functions agreeing with the plain one.
#include "hbm/solver/function_curve.hpp"

#include <gtest/gtest.h>

using hbm::solver::FunctionCurve;

TEST(FunctionCurve, InterpolatesAndExtendsEndSegments) {
  const FunctionCurve f(1, "ramp", {0.0, 1.0, 3.0}, {0.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(f(0.5), 1.0);
  EXPECT_DOUBLE_EQ(f(2.0), 2.5);
  EXPECT_DOUBLE_EQ(f(-1.0), -2.0);  // first segment extended: slope 2
  EXPECT_DOUBLE_EQ(f(5.0), 4.0);    // last segment extended: slope 0.5
  EXPECT_DOUBLE_EQ(f.slope(2.0), 0.5);
  std::size_t seg = 0;
  for (double x = -1.0; x <= 5.0; x += 0.25) EXPECT_DOUBLE_EQ(f.eval_from(x, seg), f(x)) << x;
  const FunctionCurve c(2, "const", {0.0}, {7.0});
  EXPECT_DOUBLE_EQ(c(100.0), 7.0);
}

TEST(FunctionCurve, IntegralIsExactIncludingExtension) {
  const FunctionCurve f(1, "ramp", {0.0, 1.0, 3.0}, {0.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(f.integral(0.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(f.integral(1.0, 3.0), 5.0);
  EXPECT_DOUBLE_EQ(f.integral(0.5, 2.0), 0.75 + 2.25);
  EXPECT_DOUBLE_EQ(f.integral(3.0, 5.0), 3.0 * 2 + 0.25 * 4);  // y = 3 + 0.5 (x - 3)
  EXPECT_DOUBLE_EQ(f.integral(-1.0, 0.0), -1.0);               // y = 2 x
}
