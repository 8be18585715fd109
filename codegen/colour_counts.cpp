#include "codegen/colour_counts.h"

#include <algorithm>
#include <array>
#include <memory>

#include "codegen/huge_pages.h"
#include "codegen/parallel.h"

namespace octopoint::prepare {
namespace {

constexpr std::size_t kReds = 256;
constexpr std::size_t kGreenBlue = std::size_t{1} << 16;
// A red with fewer colours than this is sorted; with more, counted in a 256 kB table.
constexpr std::size_t kTableColours = 4096;

std::size_t redOf(std::uint32_t packed) { return packed >> 16 & 0xffu; }

// The counts of one red's colours (sorted or not), ascending, appended to `out`.
void countRed(std::span<std::uint32_t> colours, std::vector<std::uint32_t>& table,
              std::vector<ColourCount>& out) {
  if (colours.size() < kTableColours) {
    std::sort(colours.begin(), colours.end());
    for (std::size_t i = 0; i < colours.size();) {
      std::size_t j = i;
      while (j < colours.size() && colours[j] == colours[i]) ++j;
      out.push_back({colours[i], static_cast<std::uint32_t>(j - i)});
      i = j;
    }
    return;
  }
  table.resize(kGreenBlue, 0);  // all zero between uses: emptied as it is read
  for (std::uint32_t c : colours) ++table[c & 0xffffu];
  const std::uint32_t red = colours[0] & 0xff0000u;
  for (std::uint32_t gb = 0; gb < kGreenBlue; ++gb) {
    if (table[gb] == 0) continue;
    out.push_back({red | gb, table[gb]});
    table[gb] = 0;
  }
}

}  // namespace

std::vector<ColourCount> countColours(std::span<const std::span<const std::uint32_t>> pieces,
                                      unsigned threads) {
  // The pieces in `threads` runs of about equal colour counts; each run counts its reds, then
  // scatters its colours to where the runs before it leave room: the grouped order is fixed.
  std::size_t total = 0;
  for (const auto& piece : pieces) total += piece.size();
  if (total == 0) return {};
  threads = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(pieces.size())));
  std::vector<std::size_t> run_start = {0};
  for (std::size_t p = 0, done = 0; p < pieces.size(); ++p) {
    done += pieces[p].size();
    if (done * threads >= total * run_start.size() && run_start.size() < threads) {
      run_start.push_back(p + 1);
    }
  }
  while (run_start.size() <= threads) run_start.push_back(pieces.size());
  std::vector<std::array<std::size_t, kReds>> counts(threads);
  parallelFor(threads, threads, [&](std::size_t run, unsigned) {
    counts[run].fill(0);
    for (std::size_t p = run_start[run]; p < run_start[run + 1]; ++p) {
      for (std::uint32_t c : pieces[p]) ++counts[run][redOf(c)];
    }
  });
  std::array<std::size_t, kReds + 1> red_start{};
  std::vector<std::array<std::size_t, kReds>> next(threads);
  for (std::size_t red = 0, at = 0; red < kReds; ++red) {
    red_start[red] = at;
    for (unsigned run = 0; run < threads; ++run) {
      next[run][red] = at;
      at += counts[run][red];
    }
    red_start[red + 1] = at;
  }
  const auto grouped = std::make_unique_for_overwrite<std::uint32_t[]>(total);
  adviseHugePages(grouped.get(), total * sizeof(std::uint32_t));
  parallelFor(threads, threads, [&](std::size_t run, unsigned) {
    for (std::size_t p = run_start[run]; p < run_start[run + 1]; ++p) {
      for (std::uint32_t c : pieces[p]) grouped[next[run][redOf(c)]++] = c;
    }
  });
  std::vector<std::vector<ColourCount>> per_red(kReds);
  std::vector<std::vector<std::uint32_t>> tables(threads);
  parallelFor(threads, kReds, [&](std::size_t red, unsigned worker) {
    const std::span<std::uint32_t> colours(grouped.get() + red_start[red],
                                           red_start[red + 1] - red_start[red]);
    if (!colours.empty()) countRed(colours, tables[worker], per_red[red]);
  });
  std::vector<ColourCount> distinct;
  std::size_t distinct_count = 0;
  for (const auto& red : per_red) distinct_count += red.size();
  distinct.reserve(distinct_count);
  for (const auto& red : per_red) distinct.insert(distinct.end(), red.begin(), red.end());
  return distinct;
}

}  // namespace octopoint::prepare
