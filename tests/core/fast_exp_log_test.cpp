// fast_exp / fast_log (libbake/core/fast_exp_log.h) against std::exp / std::log on their domains, densely and at
// the ends, and a vector lane against the scalar (the same bits).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

// 32-byte vectors passed to inlined helpers: the AVX ABI note does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "libbake/core/fast_exp_log.h"

namespace mbk {
namespace {

// Error in units of the last place of the reference.
double ulps(double value, double reference) {
  return std::abs(value - reference) / (std::nextafter(std::abs(reference), INFINITY) - std::abs(reference));
}

TEST(FastExpLog, ExpWithinTwoUlpOnItsDomain) {
  double worst = 0.0;
  for (int i = 0; i <= 2000000; ++i) {
    const double d = -64.0 * i / 2000000.0;
    worst = std::max(worst, ulps(fast_exp(d), std::exp(d)));
  }
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(fast_exp(0.0), 1.0);
  EXPECT_EQ(fast_exp(-0.0), 1.0);
}

TEST(FastExpLog, LogWithinTwoUlpOfTheSumsTheEStepTakes) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> sum(1.0, 16.0), any(-300.0, 300.0);
  double worst = 0.0;
  for (int i = 0; i < 2000000; ++i) {
    const double s = sum(rng);
    // Near s = 1 log is small: compare with the error of a correctly rounded log(s) times ~1 ulp of s.
    worst = std::max(worst, std::abs(fast_log(s) - std::log(s)) / std::max(std::abs(std::log(s)) * 0x1p-52, 0x1p-53));
  }
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(fast_log(1.0), 0.0);
  for (double s : {16.0, 2.0, std::sqrt(2.0), std::nextafter(std::sqrt(2.0), 2.0), 1e-300, 1e300})
    EXPECT_LE(ulps(fast_log(s), std::log(s)), 2.0) << s;
  for (int i = 0; i < 10000; ++i) {
    const double s = std::exp(any(rng));
    EXPECT_LE(std::abs(fast_log(s) - std::log(s)), 4e-16 * std::max(1.0, std::abs(std::log(s)))) << s;
  }
}

TEST(FastExpLog, VectorLanesGiveTheScalarBits) {
  using V = double __attribute__((vector_size(32)));
  using U = uint64_t __attribute__((vector_size(32)));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> d(-64.0, 0.0), s(1.0, 16.0);
  for (int i = 0; i < 1000; ++i) {
    V x, y;
    for (int l = 0; l < 4; ++l) x[l] = d(rng), y[l] = s(rng);
    const V ex = fast_exp<V, U>(x), ly = fast_log<V, U>(y);
    for (int l = 0; l < 4; ++l) {
      EXPECT_EQ(ex[l], fast_exp(x[l]));
      EXPECT_EQ(ly[l], fast_log(y[l]));
    }
  }
}

}  // namespace
}  // namespace mbk
