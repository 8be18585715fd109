#include "codegen/huge_pages.h"

#include <sys/mman.h>

#include <cstdint>
#include <new>

namespace octopoint::prepare {

void reserveOnHugePages(std::string& text, std::size_t bytes) {
  if (bytes <= text.capacity()) return;
  text.reserve(bytes);
  // Past the current contents: the part not written yet.
  adviseHugePages(text.data() + text.size(), text.capacity() - text.size());
}

std::shared_ptr<void> zeroedPages(std::size_t bytes) {
  void* data = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (data == MAP_FAILED) throw std::bad_alloc();
  adviseHugePages(data, bytes);
  return {data, [bytes](void* pages) { ::munmap(pages, bytes); }};
}

}  // namespace octopoint::prepare
