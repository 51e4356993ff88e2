// SPDX-License-Identifier: GPL-3.0-or-later
// Vector instructions over the lanes of a brick batch (rows of n <= 32 doubles) where GCC
// does not emit them by itself:
//  - sqrt_lanes: a[l] = sqrt(a[l]). Without -fno-math-errno GCC keeps every loop holding a
//    std::sqrt scalar (a test and a libm call for negative arguments, to set errno), and
//    the function attribute optimize("no-math-errno") does not change that (GCC 12).
//    IEEE 754 square root is correctly rounded in every form: the same bits as std::sqrt.
//    A negative argument gives NaN without errno; the kernel's arguments are sums of
//    squares or masked finite values.
//  - copy_lanes: dst[l] = src[l]. std::copy_n of a 256-byte row is a memmove call (GCC 12
//    inlines none of that size for this CPU), about 20 cycles each, 27 per batch.
// AVX (4 lanes) where the build targets it, else SSE2 (2 lanes; GCC 12's AVX-512 sqrt
// intrinsic warns of an uninitialised operand), scalar code for the rest.
#pragma once

#include <cmath>
#include <cstddef>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace hbm::solver::brick {

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

}  // namespace hbm::solver::brick
