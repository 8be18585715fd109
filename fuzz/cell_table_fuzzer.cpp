// libFuzzer harness for cell tables (renderer/cell_table.h, docs/city.md "Visibility cells"): any
// bytes either parse, for a scene of the instance count their header names, or are refused with a
// reason; a table that parses decodes every cell into sorted ids below that count, never more
// than it, and finds a cell (or none) for any eye, under ASan and UBSan.
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
  std::vector<std::uint32_t> ids(instances);
  for (std::uint32_t cell = 0; cell < table.grid().cellCount(); ++cell) {
    const std::size_t count = table.decode(cell, ids);
    if (count > instances || count > table.largestSet()) std::abort();
    for (std::size_t k = 0; k < count; ++k)
      if (ids[k] >= instances || (k > 0 && ids[k] <= ids[k - 1])) std::abort();
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
