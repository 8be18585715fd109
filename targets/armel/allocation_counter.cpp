// The replaced global operator new and delete of targets/armel/allocation_counter.h.
//
// In a translation unit of their own on purpose: where GCC can inline this operator delete (free)
// into code whose pointer it saw come from operator new, as in GoogleTest's test factories, it
// warns -Wmismatched-new-delete about a pair it cannot know belongs together.
#include "targets/armel/allocation_counter.h"

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {

std::atomic<long> g_allocation_count{0};

void* countedAllocation(std::size_t size, std::size_t alignment) {
  g_allocation_count.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  // aligned_alloc wants a multiple of the alignment; the default alignment suits malloc.
  void* memory =
      alignment <= alignof(std::max_align_t)
          ? std::malloc(size)
          : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

}  // namespace

long octopoint::heapAllocationCount() { return g_allocation_count.load(); }

// The array and nothrow forms of libstdc++ forward to these two; every delete ends in free().
void* operator new(std::size_t size) { return countedAllocation(size, alignof(std::max_align_t)); }
void* operator new(std::size_t size, std::align_val_t alignment) {
  return countedAllocation(size, static_cast<std::size_t>(alignment));
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete(void* memory, std::align_val_t) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t, std::align_val_t) noexcept { std::free(memory); }
