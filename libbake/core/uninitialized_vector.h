// std::vector whose sizing constructor and resize() leave trivially constructible elements unwritten, for a
// large buffer that a (parallel) loop then fills entirely: no zero-fill pass on one thread before it, and each
// page is first touched by the thread that writes it. Large buffers are advised onto huge pages (huge_pages.h).
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "libbake/core/huge_pages.h"

namespace mbk {

template <typename T>
struct UninitializedAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  T* allocate(size_t n) {
    T* data = std::allocator<T>::allocate(n);
    advise_huge_pages(data, n * sizeof(T));
    return data;
  }

  // Value-initialisation (vector(n), resize(n)) becomes default-initialisation; other constructions as usual.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

}  // namespace mbk
