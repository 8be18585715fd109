#pragma once
// A palette of at most 256 colours for a model: exact when the voxels have that few distinct
// colours; otherwise median cut (Heckbert 1982) over the voxels' colours, weighted by how many
// voxels have each colour, refined by a few Lloyd (k-means) passes.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "codegen/prepared_model.h"

namespace octopoint::prepare {

inline constexpr int kMaxPaletteColours = 256;

class Palette {
 public:
  // `colours` may repeat; each occurrence counts once in the weighting.
  static Palette build(std::span<const Rgb8> colours, int max_colours = kMaxPaletteColours);
  // The same from colours packed 0xRRGGBB (which it sorts): what the streamed preparer collects.
  static Palette buildPacked(std::vector<std::uint32_t> packed,
                             int max_colours = kMaxPaletteColours);
  // The same from the colours of all the pieces, on `threads` threads (the same palette for any
  // number): a large model's colours without joining them first.
  static Palette buildFromPieces(std::span<const std::span<const std::uint32_t>> pieces,
                                 int max_colours, unsigned threads);

  const std::vector<Rgb8>& colours() const { return colours_; }
  // The index of the palette colour nearest to `colour` (squared RGB distance).
  std::uint8_t indexOf(const Rgb8& colour) const;

  // indexOf for millions of colours (a large model's leaves): a direct table over all 2^24
  // colours (18 MB) answers those build() saw with one read instead of a binary search.
  class Lookup {
   public:
    explicit Lookup(const Palette& palette);
    std::uint8_t indexOf(const Rgb8& colour) const {
      const std::uint32_t p =
          std::uint32_t{colour[0]} << 16 | std::uint32_t{colour[1]} << 8 | colour[2];
      return (known_[p >> 6] >> (p & 63) & 1u) ? index_[p] : palette_.indexOf(colour);
    }

   private:
    const Palette& palette_;
    // Zeroed pages (codegen/huge_pages.h): only the parts of the tables a colour falls in are
    // ever touched.
    std::shared_ptr<void> pages_;
    std::uint8_t* index_;   // 2^24 entries
    std::uint64_t* known_;  // one bit per colour
  };

 private:
  std::vector<Rgb8> colours_;
  // Every distinct colour seen by build, packed 0xRRGGBB and sorted, with its palette index:
  // looking a voxel's colour up is then a binary search, not a 256-way scan.
  std::vector<std::uint32_t> known_colours_;
  std::vector<std::uint8_t> known_index_;
};

}  // namespace octopoint::prepare
