#pragma once
// Large buffers on 2 MB pages. Each first touch of a 4 kB page is a page fault, and in a virtual
// machine a fault costs microseconds: the preparer spent a fifth of its time in them, on buffers
// of tens of megabytes (points, colours, generated text). Asking for huge pages before the buffer
// is first written makes that one fault per 2 MB (transparent huge pages in "madvise" mode).

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace octopoint::prepare {

// Advises huge pages for the whole 2 MB pages inside [data, data + bytes); a hint, never an error.
// Inline: sources that some tests compile on their own (oct_serializer.cpp) use it too.
inline void adviseHugePages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = (start + bytes) & ~(kHugePage - 1);
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// text.reserve(bytes) on huge pages when that allocates (before anything is written there).
void reserveOnHugePages(std::string& text, std::size_t bytes);

// `bytes` of zeroed memory straight from the kernel, on huge pages: pages never touched cost
// nothing (a lookup table over all 2^24 colours of which a model uses a few thousand).
// Throws std::bad_alloc when there is no memory.
std::shared_ptr<void> zeroedPages(std::size_t bytes);

}  // namespace octopoint::prepare
