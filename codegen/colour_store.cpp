#include "codegen/colour_store.h"

#include <algorithm>
#include <cassert>

#include "codegen/huge_pages.h"

namespace octopoint::prepare {

namespace {
constexpr std::size_t kBlockColours = std::size_t{1} << 21;  // 8 MB, four huge pages
}

std::uint32_t* ColourStore::reserve(std::size_t most) {
  if (most > left_) {
    const std::size_t colours = std::max(most, kBlockColours);
    blocks_.push_back(zeroedPages(colours * sizeof(std::uint32_t)));
    next_ = static_cast<std::uint32_t*>(blocks_.back().get());
    left_ = colours;
  }
  return next_;
}

std::span<const std::uint32_t> ColourStore::commit(std::size_t used) {
  assert(used <= left_);
  const std::span<const std::uint32_t> piece(next_, used);
  next_ += used;
  left_ -= used;
  return piece;
}

}  // namespace octopoint::prepare
