// octopoint-cells-recode: a cell table (renderer/cell_table.h) written again in each encoding, to
// measure what the order and the differences save (docs/city.md, "Visibility cells") without
// building the cells again; with -o, the smallest written (an OCTCELL1 table brought to OCTCELL2).
// Every encoding is checked to decode to the same sets.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/input_file.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/run_tool.h"
#include "renderer/cell_table.h"

namespace {

using namespace octopoint;

constexpr const char* kUsage =
    R"(usage: octopoint-cells-recode CELLS [-o OUT] [--decode N]

Reads a cell table (OCTCELL1 or OCTCELL2) and prints its bytes in each encoding: OCTCELL1 (the
ids' own order, each cell its runs), OCTCELL2 with the order, with the differences, with both.
Each is checked to decode to the same sets.
  -o OUT       write the OCTCELL2 table with both
  --decode N   only decode every cell of CELLS as read, N times (to count decode's instructions:
               valgrind --tool=callgrind --toggle-collect='*CellTable::decode*')
)";

CellTable parseOrThrow(const std::vector<std::uint8_t>& bytes, std::uint32_t instances,
                       const std::string& what) {
  CellTableError why;
  CellTable table = CellTable::parse(bytes, instances, &why);
  if (why != CellTableError::kNone) throw cli::Error(what + ": cell table " + describe(why));
  return table;
}

std::vector<std::vector<std::uint32_t>> setsOf(const CellTable& table) {
  std::vector<std::uint32_t> ids(table.grid().instances);
  CellTable::Scratch scratch = table.scratch();
  std::vector<std::vector<std::uint32_t>> sets;
  for (std::uint32_t cell = 0; cell < table.grid().cellCount(); ++cell) {
    const std::size_t count = table.decode(cell, ids, scratch);
    sets.emplace_back(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(count));
    std::sort(sets.back().begin(), sets.back().end());
  }
  return sets;
}

int run(int argc, char** argv) {
  cli::ArgumentReader args(argc, argv);
  std::string input, output;
  int decodes = 0;
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (args.is("-o")) {
      output = args.value();
    } else if (args.is("--decode")) {
      decodes = cli::parseInt(args.name(), args.value(), 1, 1000000);
    } else if (args.isPlain() && input.empty()) {
      input = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (input.empty()) throw cli::Error("give CELLS (see --help)");
  const std::vector<std::uint8_t> bytes =
      cli::readInputBytes(input, cli::InputKind{"cell table", kMaxCellTableBytes});
  if (bytes.size() < 12) throw cli::Error(input + ": cell table truncated");
  const std::uint32_t instances =
      static_cast<std::uint32_t>(bytes[8]) | static_cast<std::uint32_t>(bytes[9]) << 8 |
      static_cast<std::uint32_t>(bytes[10]) << 16 | static_cast<std::uint32_t>(bytes[11]) << 24;
  const CellTable table = parseOrThrow(bytes, instances, input);
  if (decodes > 0) {  // nothing else decoded: the count is decode's alone
    std::vector<std::uint32_t> ids(table.largestSet());
    CellTable::Scratch scratch = table.scratch();
    std::uint64_t sum = 0;
    for (int k = 0; k < decodes; ++k)
      for (std::uint32_t cell = 0; cell < table.grid().cellCount(); ++cell)
        sum += table.decode(cell, ids, scratch);
    std::printf("decoded %d x %u cells: %llu ids\n", decodes, table.grid().cellCount(),
                static_cast<unsigned long long>(sum));
    return 0;
  }
  const std::vector<std::vector<std::uint32_t>> sets = setsOf(table);
  std::size_t total = 0;
  for (const auto& set : sets) total += set.size();
  std::printf("%s: %zu bytes; %u instances, %u cells, sets of %.0f on average\n", input.c_str(),
              bytes.size(), instances, table.grid().cellCount(),
              static_cast<double>(total) / static_cast<double>(sets.size()));
  struct Variant {
    const char* name;
    CellTableEncoding encoding;
  };
  std::vector<std::uint8_t> smallest;
  for (const Variant& v :
       {Variant{"OCTCELL1", {true, false, false}},
        Variant{"OCTCELL2, ids' order, own runs", {false, false, false}},
        Variant{"OCTCELL2, ids' order, differences", {false, false, true}},
        Variant{"OCTCELL2, membership order, own runs", {false, true, false}},
        Variant{"OCTCELL2, membership order, differences", {false, true, true}}}) {
    const std::vector<std::uint8_t> coded = encodeCellTable(table.grid(), sets, v.encoding);
    if (setsOf(parseOrThrow(coded, instances, v.name)) != sets)
      throw cli::Error(std::string(v.name) + ": decodes to other sets");
    std::printf("  %-42s %9zu bytes\n", v.name, coded.size());
    smallest = coded;  // the last: both
  }
  if (!output.empty())
    cli::writeFileAtomically(output,
                             {reinterpret_cast<const char*>(smallest.data()), smallest.size()});
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("octopoint-cells-recode", argc, argv, run);
}
