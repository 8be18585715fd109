// libFuzzer harness for cell tables (renderer/cell_table.h, docs/city.md "Visibility cells"): any
// bytes either parse, for a scene of the instance count their header names, or are refused with a
// reason; a table that parses (OCTCELL2 or OCTCELL1) decodes every cell, twice (the scratch bits
// left clear), into distinct ids below that count, never more than its largest set, the same both
// times, and finds a cell (or none) for any eye, under ASan and UBSan.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "renderer/cell_table.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace octopoint;
  // The scene's count: the header's own when it has one (so that tables get past that check),
  // capped so that the decode buffer stays small.
  std::uint32_t instances = 1000;
  if (size >= 12) instances = std::uint32_t{data[8]} | std::uint32_t{data[9]} << 8;
  CellTableError error;
  const CellTable table = CellTable::parse({data, size}, instances, &error);
  if (error != CellTableError::kNone) {
    if (describe(error) == nullptr) std::abort();
    return 0;
  }
  if (table.largestSet() > instances) std::abort();
  std::vector<std::uint32_t> ids(table.largestSet()), again(table.largestSet());
  CellTable::Scratch scratch = table.scratch();
  std::vector<std::uint8_t> seen(instances);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t cell = 0; cell < table.grid().cellCount(); ++cell) {
      const std::size_t count = table.decode(cell, ids, scratch);
      if (count > ids.size()) std::abort();
      for (std::size_t k = 0; k < count; ++k) {
        if (ids[k] >= instances || seen[ids[k]] != 0) std::abort();
        seen[ids[k]] = 1;
      }
      for (std::size_t k = 0; k < count; ++k) seen[ids[k]] = 0;
      if (pass == 1 && (table.decode(cell, again, scratch) != count ||
                        !std::equal(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(count),
                                    again.begin())))
        std::abort();
    }
  }
  const CellGrid& g = table.grid();
  for (const Point3<std::int64_t> eye :
       {Point3<std::int64_t>{g.origin_x, g.y.front(), g.origin_z},
        Point3<std::int64_t>{g.origin_x + g.edge * g.nx - 1, g.y.back() - 1, g.origin_z},
        Point3<std::int64_t>{INT64_MIN / 4, INT64_MAX / 4, 0}}) {
    const std::int64_t cell = table.cellAt(eye);
    if (cell < -1 || cell >= static_cast<std::int64_t>(g.cellCount())) std::abort();
  }
  return 0;
}
