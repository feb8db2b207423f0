// parallel_for never lets an exception escape its OpenMP region (that would terminate the process): what a body
// throws is rethrown after the loop, and when several indices throw, the lowest index's error is the one seen, for
// any thread count; indices below the failing one still run.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "libbake/core/parallel.h"

namespace mbk {
namespace {

struct ThreadCountGuard {
  int saved = thread_count();
  ~ThreadCountGuard() { set_thread_count(saved); }
};

TEST(ParallelFor, ExceptionInBodyIsRethrownAfterTheLoop) {
  ThreadCountGuard guard;
  for (int threads : {1, 2, 4}) {
    set_thread_count(threads);
    EXPECT_THROW(parallel_for(0, 1000,
                              [](int64_t i) {
                                if (i == 500) throw std::runtime_error("index 500");
                              }),
                 std::runtime_error)
        << threads << " threads";
  }
}

TEST(ParallelFor, LowestFailingIndexWinsWhateverTheThreadCount) {
  ThreadCountGuard guard;
  for (int threads : {1, 2, 4}) {
    set_thread_count(threads);
    std::vector<char> ran(2000, 0);
    std::string message;
    try {
      parallel_for(0, 2000, [&](int64_t i) {
        ran[size_t(i)] = 1;
        if (i % 300 == 299) throw std::runtime_error("index " + std::to_string(i));
      });
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
    EXPECT_EQ(message, "index 299") << threads << " threads";
    for (size_t i = 0; i <= 299; ++i) ASSERT_EQ(ran[i], 1) << "index " << i << " below the failure did not run";
  }
}

TEST(ParallelFor, EveryIndexRunsOnceWithoutFailures) {
  ThreadCountGuard guard;
  set_thread_count(2);
  std::vector<int> count(777, 0);
  parallel_for(0, 777, [&](int64_t i) { ++count[size_t(i)]; });
  for (int c : count) EXPECT_EQ(c, 1);
  parallel_for(5, 5, [&](int64_t) { FAIL() << "empty range ran"; });
}

}  // namespace
}  // namespace mbk
