#pragma once
// Room for the leaf colours of a large model: big blocks of zeroed pages on 2 MB pages
// (codegen/huge_pages.h), handed out in pieces that never move. Tens of millions of colours in
// vectors of their own cost a page fault per 4 kB and copies as they grew (a tenth of the
// preparer's time at 10^7 points). One store per thread: it is not thread-safe.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace octopoint::prepare {

class ColourStore {
 public:
  // Room for up to `most` colours, written through the pointer, then kept with commit().
  std::uint32_t* reserve(std::size_t most);
  // The first `used` (<= most) colours of the last reserve(); the rest goes back to the store.
  std::span<const std::uint32_t> commit(std::size_t used);

 private:
  std::vector<std::shared_ptr<void>> blocks_;
  std::uint32_t* next_ = nullptr;  // in the newest block
  std::size_t left_ = 0;           // colours free there
};

}  // namespace octopoint::prepare
