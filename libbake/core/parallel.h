// Deterministic parallel loops over OpenMP. Work is split by index, every index computes its own result
// and writes only its own slots, so outputs are byte-identical whatever the thread count (docs/ARCHITECTURE.md,
// "Determinism": "the same inputs and options give byte-identical outputs whatever --threads is"). Reductions that must
// be deterministic are done afterwards, serially, in index order.
#pragma once

#include <cstdint>

namespace mbk {

// Sets the number of threads for all later parallel loops (0 = OpenMP's default).
void set_thread_count(int threads);
int thread_count();

template <typename F>
void parallel_for(int64_t begin, int64_t end, F&& body) {
#pragma omp parallel for schedule(dynamic, 1)
  for (int64_t i = begin; i < end; ++i) body(i);
}

}  // namespace mbk
