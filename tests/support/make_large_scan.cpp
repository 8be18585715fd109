// make_large_scan: a scan of any size of the procedural landscape (tests/support/landscape.h), as
// LAS, LAZ or binary PLY, written point by point, so 10^8 points need no more memory than 100.
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "cli/arguments.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"

namespace {

using octopoint::testing::Landscape;
using octopoint::testing::LandscapePoint;
using octopoint::testing::LasLayout;

constexpr std::int64_t kMaxPoints = std::int64_t{1} << 40;

constexpr const char* kUsage =
    R"(usage: make_large_scan --points N --format las|laz|ply [options] -o FILE

Writes N points of a procedural landscape (hills, meadows, rock, a lake, a town of buildings with
coloured roofs) to FILE, point by point in constant memory; the same options give the same file.

  --points N            how many points, 1..2^40
  --format las|laz|ply  LAS; LAZ, the same compressed as LASzip does (point formats 0 to 3,
                        point-wise items version 2; formats 6 to 8, layered items version 3;
                        chunked, with a chunk table); or binary little-endian PLY (float x y z,
                        uchar red green blue)
  --chunk-points N      LAZ points per chunk (default 50000, LASzip's)
  --variable-chunks     LAZ chunks of varying sizes, listed in the chunk table
  --copc                the points ordered as a COPC octree of nodes of at most --chunk-points
                        points (point formats 6 to 8); with --format laz a COPC file (each node
                        a chunk, the hierarchy pages in an EVLR), with --format las its
                        uncompressed twin (the same records in the same order); held in memory
                        (the records, and 12 bytes per point) until written
  --varied-fields       vary every LAS field (returns, classes, scan angles, user data, point
                        sources, GPS times of interleaved flight lines; from format 6 on also
                        the four scanner channels, classification flags and near infrared;
                        extra bytes), not only those a landscape has
  --las-format F        LAS point format 0..10 (default 2: XYZ, intensity, 16-bit RGB);
                        formats 0, 1, 4, 6 and 9 have no colour, only intensity
  --las-version 1.N     LAS minor version 0..4 (default: the first that has the format)
  --colour-bits 8|16    LAS colour channels as 16-bit values (default) or as 8-bit values in
                        the 16-bit fields, as many writers do
  --extra-bytes N       user bytes after each LAS record (0..1000, default 0)
  --vlrs N              VLRs before the points (default 1); --evlrs N: EVLRs after them (1.4)
  --scale S             LAS coordinate scale in metres, 1e-6..1 (default 0.001)
  --seed N              another landscape of the same kind (default 1)
  -o FILE               where to write
)";

void writePly(const std::string& path, std::uint64_t points, const Landscape& landscape) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "ply\nformat binary_little_endian 1.0\ncomment octopoint make_large_scan landscape, "
         "metres\n"
      << "element vertex " << points << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  std::string buffer;
  for (std::uint64_t i = 0; i < points; ++i) {
    const LandscapePoint p = landscape.point(i);
    char record[15];
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const auto v = static_cast<float>(p.xyz[axis]);
      std::memcpy(record + 4 * axis, &v, 4);
    }
    std::memcpy(record + 12, p.rgb.data(), 3);
    buffer.append(record, sizeof record);
    if (buffer.size() >= (1u << 22)) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  if (!out.flush()) throw std::runtime_error("writing " + path + " failed");
}

int run(int argc, char** argv) {
  std::uint64_t points = 0;
  std::string format, output;
  LasLayout layout;
  std::uint64_t seed = 1;
  octopoint::cli::ArgumentReader args(argc, argv);
  using octopoint::cli::parseInt;
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (args.is("--points")) {
      points = static_cast<std::uint64_t>(
          octopoint::cli::parseInteger(args.name(), args.value(), 1, kMaxPoints));
    } else if (args.is("--format")) {
      const char* const formats[] = {"las", "laz", "ply"};
      format =
          formats[octopoint::cli::parseChoice(args.name(), args.value(), {"las", "laz", "ply"})];
      layout.laz = format == std::string("laz");
    } else if (args.is("--chunk-points")) {
      layout.laz_chunk_points =
          static_cast<std::uint32_t>(parseInt(args.name(), args.value(), 1, 1 << 20));
    } else if (args.is("--variable-chunks")) {
      layout.laz_variable_chunks = true;
    } else if (args.is("--copc")) {
      layout.copc = true;
    } else if (args.is("--varied-fields")) {
      layout.varied_fields = true;
    } else if (args.is("--las-format")) {
      layout.format = parseInt(args.name(), args.value(), 0, 10);
    } else if (args.is("--las-version")) {
      layout.version_minor = static_cast<int>(octopoint::cli::parseChoice(
          args.name(), args.value(), {"1.0", "1.1", "1.2", "1.3", "1.4"}));
    } else if (args.is("--colour-bits")) {
      layout.colour_16bit =
          octopoint::cli::parseChoice(args.name(), args.value(), {"8", "16"}) == 1;
    } else if (args.is("--extra-bytes")) {
      layout.extra_bytes = parseInt(args.name(), args.value(), 0, 1000);
    } else if (args.is("--vlrs")) {
      layout.vlrs = parseInt(args.name(), args.value(), 0, 1000);
    } else if (args.is("--evlrs")) {
      layout.evlrs = parseInt(args.name(), args.value(), 0, 1000);
    } else if (args.is("--scale")) {
      const double scale = octopoint::cli::parseReal(args.name(), args.value(), 1e-6, 1);
      layout.scale = {scale, scale, scale};
    } else if (args.is("--seed")) {
      seed = static_cast<std::uint64_t>(
          octopoint::cli::parseInteger(args.name(), args.value(), 0, INT64_MAX));
    } else if (args.is("-o")) {
      output = args.value();
    } else {
      args.refuseUnknown();
    }
  }
  if (points == 0 || output.empty() || format.empty()) {
    throw std::runtime_error("need --points N, --format las|laz|ply and -o FILE (see --help)");
  }
  if (layout.evlrs && layout.minor() < 4) throw std::runtime_error("--evlrs needs LAS 1.4");
  if (layout.laz && ((layout.format > 3 && layout.format < 6) || layout.format > 8)) {
    throw std::runtime_error("--format laz writes point formats 0 to 3 and 6 to 8, not " +
                             std::to_string(layout.format));
  }
  if (layout.copc && (format == "ply" || layout.format < 6 || layout.format > 8 ||
                      points > UINT32_MAX || layout.laz_variable_chunks)) {
    throw std::runtime_error(
        "--copc writes LAS or LAZ of point formats 6 to 8, at most 2^32 - 1 points, one chunk per "
        "node (no --variable-chunks)");
  }
  const Landscape landscape(seed);
  if (format == "ply") {
    writePly(output, points, landscape);
    return 0;
  }
  octopoint::testing::LasWriter writer(output, layout);
  for (std::uint64_t i = 0; i < points; ++i) writer.add(landscape.point(i));
  writer.finish();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return octopoint::cli::runTool("make_large_scan", argc, argv, run);
}
