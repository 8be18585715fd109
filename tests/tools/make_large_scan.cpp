// make_large_scan: a scan of any size of the procedural landscape (tests/tools/landscape.h), as
// LAS or binary PLY, written point by point, so 10^8 points need no more memory than 100.
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "tests/tools/landscape.h"
#include "tests/tools/las_writer.h"

namespace {

using octopoint::testing::Landscape;
using octopoint::testing::LandscapePoint;
using octopoint::testing::LasLayout;

constexpr const char* kUsage =
    R"(usage: make_large_scan --points N --format las|ply [options] -o FILE

Writes N points of a procedural landscape (hills, meadows, rock, a lake, a town of buildings with
coloured roofs) to FILE, point by point in constant memory; the same options give the same file.

  --points N            how many points (1 or more)
  --format las|ply      LAS, or binary little-endian PLY (float x y z, uchar red green blue)
  --las-format F        LAS point format 0..10 (default 2: XYZ, intensity, 16-bit RGB);
                        formats 0, 1, 4, 6 and 9 have no colour, only intensity
  --las-version 1.N     LAS minor version 0..4 (default: the first that has the format)
  --colour-bits 8|16    LAS colour channels as 16-bit values (default) or as 8-bit values in
                        the 16-bit fields, as many writers do
  --extra-bytes N       user bytes after each LAS record (0..1000, default 0)
  --vlrs N              VLRs before the points (default 1); --evlrs N: EVLRs after them (1.4)
  --scale S             LAS coordinate scale in metres (default 0.001)
  --seed N              another landscape of the same kind (default 1)
  -o FILE               where to write
)";

std::uint64_t number(const std::string& flag, const char* text, std::uint64_t low,
                     std::uint64_t high) {
  std::uint64_t value = 0;
  const char* end = text + std::strlen(text);
  const auto result = std::from_chars(text, end, value);
  if (result.ec != std::errc() || result.ptr != end || value < low || value > high) {
    throw std::runtime_error(flag + ": '" + text + "' is not a whole number in " +
                             std::to_string(low) + ".." + std::to_string(high));
  }
  return value;
}

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
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (i + 1 >= argc) throw std::runtime_error(arg + ": missing value (see --help)");
    const char* value = argv[++i];
    if (arg == "--points")
      points = number(arg, value, 1, std::uint64_t{1} << 40);
    else if (arg == "--format")
      format = value;
    else if (arg == "--las-format")
      layout.format = static_cast<int>(number(arg, value, 0, 10));
    else if (arg == "--las-version") {
      if (std::strncmp(value, "1.", 2) != 0)
        throw std::runtime_error("--las-version: expected 1.0 to 1.4");
      layout.version_minor = static_cast<int>(number(arg, value + 2, 0, 4));
    } else if (arg == "--colour-bits")
      layout.colour_16bit = number(arg, value, 8, 16) == 16;
    else if (arg == "--extra-bytes")
      layout.extra_bytes = static_cast<int>(number(arg, value, 0, 1000));
    else if (arg == "--vlrs")
      layout.vlrs = static_cast<int>(number(arg, value, 0, 1000));
    else if (arg == "--evlrs")
      layout.evlrs = static_cast<int>(number(arg, value, 0, 1000));
    else if (arg == "--scale") {
      const double scale = std::stod(value);
      layout.scale = {scale, scale, scale};
    } else if (arg == "--seed")
      seed = number(arg, value, 0, UINT64_MAX);
    else if (arg == "-o")
      output = value;
    else
      throw std::runtime_error("unknown option '" + arg + "' (see --help)");
  }
  if (points == 0 || output.empty() || (format != "las" && format != "ply")) {
    throw std::runtime_error("need --points N, --format las|ply and -o FILE (see --help)");
  }
  if (layout.evlrs && layout.minor() < 4) throw std::runtime_error("--evlrs needs LAS 1.4");
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
  try {
    return run(argc, argv);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "make_large_scan: %s\n", error.what());
    return 1;
  }
}
