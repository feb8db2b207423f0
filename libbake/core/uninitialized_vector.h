// std::vector whose sizing constructor and resize() leave trivially constructible elements unwritten, for a
// large buffer that a (parallel) loop then fills entirely: no zero-fill pass on one thread before it, and each
// page is first touched by the thread that writes it.
#pragma once

#include <memory>
#include <utility>
#include <vector>

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
