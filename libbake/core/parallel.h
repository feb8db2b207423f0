// Deterministic parallel loops over OpenMP. Work is split by index, every index computes its own result
// and writes only its own slots, so outputs are byte-identical whatever the thread count (docs/ARCHITECTURE.md,
// "Determinism": "the same inputs and options give byte-identical outputs whatever --threads is"). Reductions that must
// be deterministic are done afterwards, serially, in index order.
//
// No exception may leave an OpenMP region (it would call std::terminate), so parallel_for catches what a body
// throws and rethrows it after the loop. When several indices fail, the one rethrown is that of the lowest index
// (indices above a failed one are skipped, those below still run), so the error is the same for every thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>

namespace mbk {

// Sets the number of threads for all later parallel loops (0 = OpenMP's default).
void set_thread_count(int threads);
int thread_count();

template <typename F>
void parallel_for(int64_t begin, int64_t end, F&& body) {
  std::atomic<int64_t> first_failed{std::numeric_limits<int64_t>::max()};
  std::exception_ptr failure;
  std::mutex failure_mutex;
#pragma omp parallel for schedule(dynamic, 1)
  for (int64_t i = begin; i < end; ++i) {
    if (i > first_failed.load(std::memory_order_relaxed)) continue;
    try {
      body(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (i < first_failed.load()) {
        first_failed.store(i);
        failure = std::current_exception();
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace mbk
