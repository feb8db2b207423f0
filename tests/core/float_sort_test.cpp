// Linear-time float sorting (libbake/core/float_sort.h) gives std::sort's order on every kind of float: random
// values of every magnitude and sign, subnormals, zeros of both signs (-0 first), infinities, ties, and the
// empty and one-element arrays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "libbake/core/float_sort.h"
#include "libbake/core/hash.h"

namespace mbk {
namespace {

TEST(FloatSort, MatchesStdSortOnEveryKindOfFloat) {
  std::vector<float> v;
  for (uint32_t i = 0; i < 200000; ++i) {
    uint32_t bits = hash3(i, 17, 3);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    if (std::isnan(f)) f = float(i % 7) - 3.0f;  // ties among small integers
    v.push_back(f);
  }
  const float specials[] = {0.0f,
                            -0.0f,
                            std::numeric_limits<float>::denorm_min(),
                            -std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::min(),
                            std::numeric_limits<float>::max(),
                            -std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            1.0f,
                            1.0f,
                            -1.0f};
  v.insert(v.end(), std::begin(specials), std::end(specials));
  std::vector<float> expected = v;
  std::sort(expected.begin(), expected.end());
  sort_floats(v);
  ASSERT_EQ(v.size(), expected.size());
  for (size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], expected[i]) << i;  // -0 == +0 compares equal
  for (size_t i = 0; i + 1 < v.size(); ++i) {
    if (v[i] == 0.0f && v[i + 1] == 0.0f) {
      EXPECT_FALSE(!std::signbit(v[i]) && std::signbit(v[i + 1])) << "+0 before -0";
    }
  }
}

TEST(FloatSort, EmptyAndSingle) {
  std::vector<float> empty;
  sort_floats(empty);
  EXPECT_TRUE(empty.empty());
  std::vector<float> one = {-2.5f};
  sort_floats(one);
  EXPECT_EQ(one, std::vector<float>{-2.5f});
}

}  // namespace
}  // namespace mbk
