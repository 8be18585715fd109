// Writes the broken LAS files the CLI error tests feed octopoint-prepare
// (tests/large_scan_tests.cmake): a good small file from the landscape, then one damaged copy per
// kind of lie. Each must end in one line on stderr, exit status 1 and no output.
// tests/preparer/las_reader_test.cpp damages many more fields. usage: make_bad_las OUTDIR
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"

namespace {

namespace fs = std::filesystem;
namespace las = octopoint::testing::las_offsets;

std::string readAll(const fs::path& path) {
  std::string bytes(fs::file_size(path), '\0');
  std::ifstream(path, std::ios::binary)
      .read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bytes;
}

void writeAll(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

template <typename T>
std::string patched(std::string bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
  return bytes;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_bad_las OUTDIR\n");
    return 1;
  }
  const fs::path out = argv[1];
  fs::create_directories(out);
  octopoint::testing::LasLayout layout;
  layout.format = 3;
  layout.version_minor = 4;  // the 64-bit count
  const fs::path good = out / "good.las";
  {
    octopoint::testing::LasWriter writer(good, layout);
    const octopoint::testing::Landscape landscape;
    for (std::uint64_t i = 0; i < 2000; ++i) writer.add(landscape.point(i));
    writer.finish();
  }
  const std::string bytes = readAll(good);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  writeAll(out / "count_lies.las",
           patched<std::uint64_t>(patched<std::uint32_t>(bytes, las::kLegacyCount, 0), las::kCount,
                                  2001));
  writeAll(out / "count_2e64.las",
           patched<std::uint64_t>(patched<std::uint32_t>(bytes, las::kLegacyCount, 0), las::kCount,
                                  ~std::uint64_t{0}));
  writeAll(out / "truncated.las", bytes.substr(0, bytes.size() - 1000));
  writeAll(out / "scale_zero.las", patched<double>(bytes, las::kScale, 0.0));
  writeAll(out / "scale_huge.las", patched<double>(bytes, las::kScale + 8, 1e300));
  writeAll(out / "offset_nan.las", patched<double>(bytes, las::kOffset + 16, nan));
  writeAll(out / "vlr_overrun.las", patched<std::uint16_t>(bytes, 375 + 20, 65535));
  writeAll(out / "compressed.laz", patched<std::uint8_t>(bytes, las::kFormat, 0x83));
  // A terabyte that is almost all hole, its header declaring it as points.
  const std::uint64_t point_offset = readAll(good).size() - 2000 * 34;
  const std::uint64_t count = ((std::uint64_t{1} << 40) - point_offset) / 34;
  const fs::path sparse = out / "sparse_1tb.las";
  writeAll(sparse, patched<std::uint64_t>(patched<std::uint32_t>(bytes, las::kLegacyCount, 0),
                                          las::kCount, count));
  if (::truncate(sparse.c_str(), static_cast<off_t>(point_offset + count * 34)) != 0) {
    std::perror("make_bad_las: truncate");
    return 1;
  }
  return 0;
}
