#include "codegen/palette.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <limits>
#include <utility>

#include "codegen/colour_counts.h"
#include "codegen/huge_pages.h"
#include "codegen/parallel.h"

namespace octopoint::prepare {
namespace {

constexpr int kLloydPasses = 4;

struct WeightedColour {
  Rgb8 rgb;
  std::uint32_t weight;
};

std::uint32_t pack(const Rgb8& c) {
  return std::uint32_t{c[0]} << 16 | std::uint32_t{c[1]} << 8 | c[2];
}

int squaredDistance(const Rgb8& a, const Rgb8& b) {
  int sum = 0;
  for (std::size_t ch = 0; ch < 3; ++ch) {
    const int d = int{a[ch]} - int{b[ch]};
    sum += d * d;
  }
  return sum;
}

std::size_t nearest(const std::vector<Rgb8>& palette, const Rgb8& colour) {
  std::size_t best = 0;
  int best_distance = std::numeric_limits<int>::max();
  for (std::size_t i = 0; i < palette.size(); ++i) {
    const int distance = squaredDistance(palette[i], colour);
    if (distance < best_distance) {
      best_distance = distance;
      best = i;
    }
  }
  return best;
}

Rgb8 weightedMean(std::span<const WeightedColour> colours) {
  std::array<std::uint64_t, 3> sum{};
  std::uint64_t weight = 0;
  for (const WeightedColour& c : colours) {
    for (std::size_t ch = 0; ch < 3; ++ch) sum[ch] += std::uint64_t{c.rgb[ch]} * c.weight;
    weight += c.weight;
  }
  Rgb8 mean{};
  for (std::size_t ch = 0; ch < 3; ++ch)
    mean[ch] = static_cast<std::uint8_t>((sum[ch] + weight / 2) / weight);
  return mean;
}

// Median cut: split the box with the widest channel range at its weighted median until there are
// `max_colours` boxes or no box holds two distinct colours.
std::vector<Rgb8> medianCut(std::vector<WeightedColour> colours, int max_colours) {
  struct Box {
    std::size_t begin, end;
  };
  std::vector<Box> boxes = {{0, colours.size()}};
  auto widest = [&](const Box& box, std::size_t* channel) {
    int best_range = -1;
    for (std::size_t ch = 0; ch < 3; ++ch) {
      int low = 255, high = 0;
      for (std::size_t i = box.begin; i < box.end; ++i) {
        low = std::min<int>(low, colours[i].rgb[ch]);
        high = std::max<int>(high, colours[i].rgb[ch]);
      }
      if (high - low > best_range) {
        best_range = high - low;
        *channel = ch;
      }
    }
    return best_range;
  };
  while (static_cast<int>(boxes.size()) < max_colours) {
    std::size_t split = boxes.size();
    std::size_t channel = 0;
    int best_range = 0;
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      std::size_t ch = 0;
      const int range = widest(boxes[b], &ch);
      if (range > best_range) {
        best_range = range;
        split = b;
        channel = ch;
      }
    }
    if (split == boxes.size()) break;  // every box holds a single colour
    Box& box = boxes[split];
    auto first = colours.begin() + static_cast<std::ptrdiff_t>(box.begin);
    auto last = colours.begin() + static_cast<std::ptrdiff_t>(box.end);
    std::sort(first, last, [&](const WeightedColour& a, const WeightedColour& b) {
      return a.rgb[channel] < b.rgb[channel];
    });
    std::uint64_t total = 0;
    for (auto it = first; it != last; ++it) total += it->weight;
    // The weighted median, clamped so that both halves keep at least one colour.
    std::uint64_t running = 0;
    std::size_t cut = box.begin;
    while (cut < box.end && 2 * (running + colours[cut].weight) <= total)
      running += colours[cut++].weight;
    cut = std::clamp(cut, box.begin + 1, box.end - 1);
    boxes.push_back({cut, box.end});
    boxes[split].end = cut;
  }
  std::vector<Rgb8> palette;
  for (const Box& box : boxes) {
    palette.push_back(weightedMean({colours.data() + box.begin, box.end - box.begin}));
  }
  return palette;
}

void refineLloyd(std::vector<Rgb8>& palette, std::span<const WeightedColour> colours) {
  for (int pass = 0; pass < kLloydPasses; ++pass) {
    std::vector<std::array<std::uint64_t, 4>> sums(palette.size());  // r, g, b, weight
    for (const WeightedColour& c : colours) {
      auto& s = sums[nearest(palette, c.rgb)];
      for (std::size_t ch = 0; ch < 3; ++ch) s[ch] += std::uint64_t{c.rgb[ch]} * c.weight;
      s[3] += c.weight;
    }
    for (std::size_t i = 0; i < palette.size(); ++i) {
      if (sums[i][3] == 0) continue;  // an entry nobody chose keeps its colour
      for (std::size_t ch = 0; ch < 3; ++ch) {
        palette[i][ch] = static_cast<std::uint8_t>((sums[i][ch] + sums[i][3] / 2) / sums[i][3]);
      }
    }
  }
}

}  // namespace

Palette Palette::build(std::span<const Rgb8> colours, int max_colours) {
  std::vector<std::uint32_t> packed;
  packed.reserve(colours.size());
  for (const Rgb8& c : colours) packed.push_back(pack(c));
  return buildPacked(std::move(packed), max_colours);
}

Palette Palette::buildPacked(std::vector<std::uint32_t> packed, int max_colours) {
  const std::span<const std::uint32_t> piece(packed);
  return buildFromPieces({&piece, 1}, max_colours, 1);
}

Palette Palette::buildFromPieces(std::span<const std::span<const std::uint32_t>> pieces,
                                 int max_colours, unsigned threads) {
  assert(max_colours >= 1 && max_colours <= kMaxPaletteColours);
  std::vector<WeightedColour> distinct;
  {
    const std::vector<ColourCount> counts = countColours(pieces, threads);
    distinct.reserve(counts.size());
    for (const ColourCount& c : counts) {
      const std::uint32_t p = c.packed;
      distinct.push_back({Rgb8{static_cast<std::uint8_t>(p >> 16),
                               static_cast<std::uint8_t>(p >> 8), static_cast<std::uint8_t>(p)},
                          c.count});
    }
  }

  Palette palette;
  if (distinct.empty()) {
    palette.colours_ = {Rgb8{255, 255, 255}};
    return palette;
  }
  if (static_cast<int>(distinct.size()) <= max_colours) {
    for (const WeightedColour& c : distinct) palette.colours_.push_back(c.rgb);
  } else {
    palette.colours_ = medianCut(distinct, max_colours);
    refineLloyd(palette.colours_, distinct);
  }
  palette.known_colours_.resize(distinct.size());
  palette.known_index_.resize(distinct.size());
  constexpr std::size_t kBlock = 4096;  // distinct colours matched by one task
  parallelFor(threads, (distinct.size() + kBlock - 1) / kBlock, [&](std::size_t block, unsigned) {
    const std::size_t end = std::min(distinct.size(), (block + 1) * kBlock);
    for (std::size_t i = block * kBlock; i < end; ++i) {
      palette.known_colours_[i] = pack(distinct[i].rgb);
      palette.known_index_[i] =
          static_cast<std::uint8_t>(nearest(palette.colours_, distinct[i].rgb));
    }
  });
  return palette;
}

Palette::Lookup::Lookup(const Palette& palette)
    : palette_(palette), pages_(zeroedPages((std::size_t{1} << 24) + (std::size_t{1} << 24) / 8)) {
  index_ = static_cast<std::uint8_t*>(pages_.get());
  known_ = reinterpret_cast<std::uint64_t*>(index_ + (std::size_t{1} << 24));
  for (std::size_t i = 0; i < palette.known_colours_.size(); ++i) {
    const std::uint32_t p = palette.known_colours_[i];
    index_[p] = palette.known_index_[i];
    known_[p >> 6] |= std::uint64_t{1} << (p & 63);
  }
}

std::uint8_t Palette::indexOf(const Rgb8& colour) const {
  const std::uint32_t p = pack(colour);
  const auto it = std::lower_bound(known_colours_.begin(), known_colours_.end(), p);
  if (it != known_colours_.end() && *it == p) {
    return known_index_[static_cast<std::size_t>(it - known_colours_.begin())];
  }
  return static_cast<std::uint8_t>(nearest(colours_, colour));
}

}  // namespace octopoint::prepare
