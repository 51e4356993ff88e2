// SPDX-License-Identifier: GPL-3.0-or-later
// Vector instructions over the lanes of an element batch (rows of n <= 32 doubles: bricks,
// tetras, shells) where GCC does not emit them by itself, or libm calls that keep a loop
// scalar:
//  - sqrt_lanes: a[l] = sqrt(a[l]). Without -fno-math-errno GCC keeps every loop holding a
//    std::sqrt scalar (a test and a libm call for negative arguments, to set errno), and
//    the function attribute optimize("no-math-errno") does not change that (GCC 12).
//    IEEE 754 square root is correctly rounded in every form: the same bits as std::sqrt.
//    A negative argument gives NaN without errno; the kernel's arguments are sums of
//    squares or masked finite values.
//  - copy_lanes: dst[l] = src[l]. std::copy_n of a 256-byte row is a memmove call (GCC 12
//    inlines none of that size for this CPU), about 20 cycles each, 27 per batch.
//  - cbrt_lanes: out[l] = cbrt(x[l]), glibc's algorithm (sysdeps/ieee754/dbl-64/s_cbrt.c:
//    frexp, degree-6 polynomial, one rational Halley step, 2^(e/3) factor, ldexp) with
//    frexp/ldexp as exponent bit operations for positive normal x and without fused
//    multiply-adds, so the same bits as glibc's std::cbrt (checked on 12.8 million values,
//    2^-60 .. 2^60, and in solid_lane_vector_ops_test: within 1 ulp of std::cbrt
//    whatever the libm) at about 1.6 ns per value against 9 for the libm call (whose
//    call, frexp and scalbn cost 4 % of the hub run). Other x (zero, subnormal,
//    infinite, NaN, negative) take std::cbrt.
// AVX (4 lanes) where the build targets it, else SSE2 (2 lanes; GCC 12's AVX-512 sqrt
// intrinsic warns of an uninitialised operand), scalar code for the rest.
#pragma once

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace hbm::solver::lanes {

inline void sqrt_lanes(std::size_t n, double* a) {
  std::size_t l = 0;
#if defined(__AVX__)
  for (; l + 4 <= n; l += 4) _mm256_storeu_pd(a + l, _mm256_sqrt_pd(_mm256_loadu_pd(a + l)));
#endif
#if defined(__SSE2__)
  for (; l + 2 <= n; l += 2) _mm_storeu_pd(a + l, _mm_sqrt_pd(_mm_loadu_pd(a + l)));
#endif
  for (; l < n; ++l) a[l] = std::sqrt(a[l]);
}

inline void copy_lanes(std::size_t n, const double* __restrict src, double* __restrict dst) {
  std::size_t l = 0;
#if defined(__AVX__)
  for (; l + 4 <= n; l += 4) _mm256_storeu_pd(dst + l, _mm256_loadu_pd(src + l));
#endif
#if defined(__SSE2__)
  for (; l + 2 <= n; l += 2) _mm_storeu_pd(dst + l, _mm_loadu_pd(src + l));
#endif
  for (; l < n; ++l) dst[l] = src[l];
}

// fp-contract=off: glibc's cbrt is compiled without FMA; a fused a*b+c rounds once and
// would change the last bit.
[[gnu::optimize("fp-contract=off")]] inline void cbrt_lanes(std::size_t n, const double* __restrict x,
                                                             double* __restrict out) {
  constexpr double kCbrt2 = 1.2599210498948731648;     // 2^(1/3)
  constexpr double kSqrCbrt2 = 1.5874010519681994748;  // 2^(2/3)
  constexpr double kFactor[5] = {1.0 / kSqrCbrt2, 1.0 / kCbrt2, 1.0, kCbrt2, kSqrCbrt2};
  constexpr std::uint64_t kMantissa = 0x000fffffffffffffULL;
  for (std::size_t l = 0; l < n; ++l) {
    // frexp: x = xm 2^xe, 0.5 <= xm < 1 (x positive normal).
    const auto bits = std::bit_cast<std::uint64_t>(x[l]);
    const int xe = static_cast<int>((bits >> 52) & 0x7ff) - 1022;
    const double xm = std::bit_cast<double>((bits & kMantissa) | (std::uint64_t{1022} << 52));
    const double u =
        (0.354895765043919860 +
         ((1.50819193781584896 +
           ((-2.11499494167371287 +
             ((2.44693122563534430 + ((-1.83469277483613086 + (0.784932344976639262 - 0.145263899385486377 * xm) * xm) * xm)) *
              xm)) *
            xm)) *
          xm));
    const double t2 = u * u * u;
    const double ym = u * (t2 + 2.0 * xm) / (2.0 * t2 + xm) * kFactor[2 + xe % 3];
    // ldexp(ym, xe / 3): a product with a power of two, exact while the result is normal.
    out[l] = ym * std::bit_cast<double>(static_cast<std::uint64_t>(xe / 3 + 1023) << 52);
  }
  for (std::size_t l = 0; l < n; ++l)
    if (!(x[l] >= DBL_MIN && x[l] <= DBL_MAX)) out[l] = std::cbrt(x[l]);
}

}  // namespace hbm::solver::lanes
