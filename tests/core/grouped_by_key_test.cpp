// group_by_key (libbake/core/grouped_by_key.h) against std::stable_sort by key of the lists joined in order, and
// floating-point sums per key equal bit for bit to the sums accumulated in that order.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "libbake/core/grouped_by_key.h"

namespace mbk {
namespace {

struct Record {
  size_t key;
  double value;
};

TEST(GroupedByKey, IsAStableSortByKeyOfTheListsInOrderWithEveryKeysRange) {
  for (const size_t keys : {size_t(1), size_t(7), size_t(100000)}) {
    std::mt19937 rng{unsigned(keys)};
    std::uniform_int_distribution<size_t> key(0, std::min<size_t>(keys, 50) - 1);  // most keys empty when many
    std::uniform_real_distribution<double> value(-1e6, 1e6);
    std::vector<Record> in(20000);
    for (Record& r : in) r = {key(rng), value(rng)};
    // The records in three lists of unequal lengths (one empty), as chunks of a parallel producer would be.
    std::vector<std::vector<Record>> lists = {
        std::vector<Record>(in.begin(), in.begin() + 5000), {}, std::vector<Record>(in.begin() + 5000, in.end())};
    const GroupedByKey<Record> g = group_by_key(std::move(lists), keys, [](const Record& r) { return r.key; });
    for (const std::vector<Record>& list : lists) EXPECT_EQ(list.capacity(), 0u);  // consumed: freed once placed
    std::vector<Record> sorted = in;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Record& a, const Record& b) { return a.key < b.key; });
    ASSERT_EQ(g.records.size(), sorted.size());
    for (size_t i = 0; i < sorted.size(); ++i) {
      EXPECT_EQ(g.records[i].key, sorted[i].key);
      EXPECT_EQ(g.records[i].value, sorted[i].value);
    }
    std::vector<double> running(keys, 0.0);
    for (const Record& r : in) running[r.key] += r.value;
    for (size_t k = 0; k < keys; ++k) {
      double sum = 0.0;
      for (size_t i = g.begin(k); i < g.end(k); ++i) {
        EXPECT_EQ(g.records[i].key, k);
        sum += g.records[i].value;
      }
      EXPECT_EQ(sum, running[k]) << k;  // bit for bit: the same additions in the same order
    }
    EXPECT_EQ(g.begin(0), 0u);
    EXPECT_EQ(g.end(keys - 1), in.size());
  }
}

TEST(GroupedByKey, NoRecordsGiveEmptyGroups) {
  const GroupedByKey<Record> g =
      group_by_key(std::vector<std::vector<Record>>{}, 3, [](const Record& r) { return r.key; });
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(g.begin(k), g.end(k));
  EXPECT_TRUE(g.records.empty());
}

}  // namespace
}  // namespace mbk
