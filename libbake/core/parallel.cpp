// Thread-count control for parallel_for (see parallel.h).
#include "libbake/core/parallel.h"

#include <omp.h>

namespace mbk {

void set_thread_count(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

int thread_count() { return omp_get_max_threads(); }

}  // namespace mbk
