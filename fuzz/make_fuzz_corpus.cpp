// Writes the fuzzers' seed corpus into OUTDIR/model and OUTDIR/scan_header:
//  - model: the default embedded model (a real Kinect scan, as octopoint-prepare wrote it) as a
//    `.oct` file, and the same scan coarsened to every smaller depth, so the fuzzer starts from
//    real trees of every size;
//  - scan_header: one small, valid scan per PCD/PLY encoding the checker knows;
//  - chunked: the default model as chunked files (format version 3) of a few depth sets, read
//    whole (first byte 0), and splices into the harness's own model at the head, a record table
//    and a chunk (first byte 3: spliced, CRCs recomputed). See fuzz/chunked_fuzzer.cpp.
//  - las: a small LAS file of every point format, and 1.0, 1.1 and 1.4 with VLRs, EVLRs and extra
//    bytes (tests/support/las_writer.h), so the fuzzer starts from every layout the reader knows.
//  - laz: small LAZ files of point formats 0 to 3 and 6 to 8, fixed and variable chunks of a few
//    points, and a COPC file whose hierarchy has child pages.
//  - cell_table: a cell table (renderer/cell_table.h) of a small grid
//  - scene: scene files (docs/city.md) of one and of several models and instances, turned, scaled
//    and at the coordinates' limits.
// usage: make_fuzz_corpus OUTDIR
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "octopoint/models.h"
#include "renderer/cell_table.h"
#include "tests/support/landscape.h"
#include "tests/support/las_writer.h"
#include "tests/support/model_images.h"

namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

void write(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  write(path, bytes.data(), bytes.size());
}
void write(const fs::path& path, const std::string& text) { write(path, text.data(), text.size()); }

std::string binaryPoints(int count) {
  std::string body;
  for (int i = 0; i < count; ++i) {
    const float xyz[3] = {0.1f * static_cast<float>(i), 0.5f, 1.0f + 0.01f * static_cast<float>(i)};
    body.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  return body;
}

void writeScanHeaders(const fs::path& dir) {
  const std::string pcd_head =
      "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\n"
      "TYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\n";
  write(dir / "ascii.pcd",
        pcd_head + "DATA ascii\n0 0 1 4278190335\n0.5 0.25 1.5 4278255360\n1 1 2 4294901760\n");
  const std::string xyz_head =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\n";
  write(dir / "binary.pcd", xyz_head + "DATA binary\n" + binaryPoints(4));
  // binary_compressed: u32 compressed size, u32 uncompressed size, then LZF data (here a single
  // literal run: control byte = length - 1, up to 32 bytes per run).
  std::string raw = binaryPoints(2);
  std::string lzf;
  for (std::size_t at = 0; at < raw.size(); at += 32) {
    const std::string run = raw.substr(at, 32);
    lzf += static_cast<char>(run.size() - 1);
    lzf += run;
  }
  const std::uint32_t sizes[2] = {static_cast<std::uint32_t>(lzf.size()),
                                  static_cast<std::uint32_t>(raw.size())};
  std::string compressed_head = xyz_head;
  compressed_head.replace(compressed_head.find("WIDTH 4"), 7, "WIDTH 2");
  compressed_head.replace(compressed_head.find("POINTS 4"), 8, "POINTS 2");
  write(dir / "compressed.pcd", compressed_head + "DATA binary_compressed\n" +
                                    std::string(reinterpret_cast<const char*>(sizes), 8) + lzf);
  const std::string ply_head =
      "ply\nformat ascii 1.0\ncomment made by make_fuzz_corpus\nelement vertex 3\nproperty float "
      "x\n"
      "property float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty "
      "uchar blue\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  write(dir / "ascii.ply", ply_head + "0 0 1 255 0 0\n1 0 1 0 255 0\n0 1 1 0 0 255\n3 0 1 2\n");
  write(
      dir / "binary.ply",
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n" +
          binaryPoints(4));
}

void writeChunkedSeeds(const fs::path& dir, const octopoint::EmbeddedModel& model) {
  fs::create_directories(dir);
  const std::vector<std::vector<int>> depth_sets = {{}, {3, 5}, {4, 6, 8}, {5, 6, 7, 8}};
  for (std::size_t i = 0; i < depth_sets.size(); ++i) {
    std::vector<std::uint8_t> seed{0};
    const std::vector<std::uint8_t> image =
        octopoint::fuzzing::chunkedImage(model, depth_sets[i], {512, 1500});
    seed.insert(seed.end(), image.begin(), image.end());
    write(dir / ("whole_" + std::to_string(i) + ".bin"), seed);
  }
  // Splices of 16 bytes of the harness's own model, at the fixed header, the level table, the first
  // record table and the first chunk: the fuzzer mutates from there.
  const std::vector<std::uint8_t> real =
      octopoint::fuzzing::chunkedImage(model, {5, 6, 7, 8}, {512, 1500});
  const std::uint32_t head_bytes = static_cast<std::uint32_t>(real[20] | real[21] << 8);
  for (std::uint32_t offset : {6u, 40u + 3u * 256u, head_bytes, head_bytes + 400u}) {
    std::vector<std::uint8_t> seed{3, static_cast<std::uint8_t>(offset),
                                   static_cast<std::uint8_t>(offset >> 8), 0, 0};
    seed.insert(seed.end(), real.begin() + offset, real.begin() + offset + 16);
    write(dir / ("splice_" + std::to_string(offset) + ".bin"), seed);
  }
}

void writeLasSeeds(const fs::path& dir) {
  using octopoint::testing::LasLayout;
  const octopoint::testing::Landscape landscape;
  auto las = [&](const std::string& name, const LasLayout& layout) {
    octopoint::testing::LasWriter writer(dir / name, layout);
    for (std::uint64_t i = 0; i < 12; ++i) writer.add(landscape.point(i));
    writer.finish();
  };
  for (int format = 0; format <= 10; ++format) {
    LasLayout layout;
    layout.format = format;
    layout.vlrs = 0;
    las("format" + std::to_string(format) + ".las", layout);
  }
  LasLayout old;
  old.format = 1;
  old.version_minor = 0;
  las("v10.las", old);
  LasLayout rich;
  rich.format = 7;
  rich.vlrs = 2;
  rich.evlrs = 1;
  rich.extra_bytes = 3;
  las("rich.las", rich);
}

// Small LAZ files of every point format the tests' encoder writes (0 to 3 point-wise, 6 to 8
// layered), every field varied, in chunks of a few points, fixed and variable, and a COPC file
// (laz_fuzzer).
void writeLazSeeds(const fs::path& dir) {
  using octopoint::testing::LasLayout;
  const octopoint::testing::Landscape landscape;
  for (int format : {0, 1, 2, 3, 6, 7, 8}) {
    for (bool variable : {false, true}) {
      LasLayout layout;
      layout.format = format;
      layout.vlrs = 0;
      layout.laz = true;
      layout.varied_fields = true;
      layout.laz_chunk_points = 5;
      layout.laz_variable_chunks = variable;
      layout.extra_bytes = format == 3 || format == 8 ? 2 : 0;
      const std::string name =
          "format" + std::to_string(format) + (variable ? "_variable" : "") + ".laz";
      octopoint::testing::LasWriter writer(dir / name, layout);
      for (std::uint64_t i = 0; i < 12; ++i) writer.add(landscape.point(i));
      writer.finish();
    }
  }
  // COPC: nodes of at most 2 points, so that the hierarchy has child pages.
  LasLayout layout;
  layout.format = 7;
  layout.vlrs = 0;
  layout.laz = true;
  layout.copc = true;
  layout.laz_chunk_points = 2;
  octopoint::testing::LasWriter writer(dir / "copc.laz", layout);
  for (std::uint64_t i = 0; i < 60; ++i) writer.add(landscape.point(i));
  writer.finish();
}

}  // namespace

void writeSceneSeeds(const fs::path& dir) {
  fs::create_directories(dir);
  write(dir / "one.json",
        std::string(R"({"models": ["tabletop"], "instances": [[0, 0, 0, 0, 0, 0]]})"));
  write(dir / "several.json",
        std::string(
            R"({"models": ["tower.oct", "tree.oct"], "instances": [[0, 0, -8388608, 0, 0, 0], )"
            R"([1, 33554432, -2097152, -16777216, 16384, -2], [0, -50331648, 0, 1, 65535, 8]]})"));
  write(
      dir / "limits.json",
      std::string(R"({"models": ["a.oct"], "instances": [[0, 17592186044416, -17592186044416, 0, )"
                  R"(32768, -8], [0, 0, 0, -17592186044416, 1, 8]]})"));
}

// Cell tables (renderer/cell_table.h): a small grid of two layers, sets empty, short, whole and
// near their neighbours' (so that OCTCELL2 codes some as differences, in a reordered table), and
// the same in OCTCELL1.
void writeCellTableSeeds(const fs::path& dir) {
  fs::create_directories(dir);
  octopoint::CellGrid grid;
  grid.instances = 300;
  grid.nx = 3;
  grid.nz = 2;
  grid.ny = 2;
  grid.origin_x = -3 << 24;
  grid.origin_z = -2 << 24;
  grid.edge = 2 << 24;
  grid.y = {-4 << 24, -(1 << 22), -(1 << 18)};
  std::vector<std::vector<std::uint32_t>> sets(12);
  sets[0] = {0, 1, 2, 7, 299};
  for (std::uint32_t i = 0; i < 300; i += 2) sets[5].push_back(i);
  for (std::uint32_t i = 0; i < 300; ++i) sets[11].push_back(i);
  for (std::uint32_t i = 1; i < 300; i += 2) sets[4].push_back(i);
  sets[3] = sets[4];
  sets[3].push_back(298);  // sorted: 298 is even, after 297
  std::swap(sets[3][sets[3].size() - 1], sets[3][sets[3].size() - 2]);
  for (std::uint32_t i = 0; i < 300; i += 3) sets[6].push_back(i);
  sets[9] = sets[6];
  sets[9].erase(sets[9].begin() + 10);
  write(dir / "small.cells", octopoint::encodeCellTable(grid, sets));
  write(dir / "small_v1.cells", octopoint::encodeCellTable(grid, sets, {true, false, false}));
}

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_fuzz_corpus OUTDIR\n");
    return 1;
  }
  try {
    const fs::path out = argv[1];
    fs::create_directories(out / "model");
    fs::create_directories(out / "scan_header");
    fs::create_directories(out / "las");
    fs::create_directories(out / "laz");
    const octopoint::EmbeddedModel& model = *octopoint::models::defaultModel();
    write(out / "model" / (std::string(model.name) + ".oct"), octopoint::fuzzing::octImage(model));
    const int finest = model.levels[model.level_count - 1].depth;
    for (int depth = 1; depth < finest; ++depth) {
      write(out / "model" / (std::string(model.name) + "_depth" + std::to_string(depth) + ".oct"),
            octopoint::fuzzing::coarsenedOctImage(model, depth));
    }
    writeScanHeaders(out / "scan_header");
    writeChunkedSeeds(out / "chunked", model);
    writeLasSeeds(out / "las");
    writeLazSeeds(out / "laz");
    writeSceneSeeds(out / "scene");
    writeCellTableSeeds(out / "cell_table");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "make_fuzz_corpus: %s\n", error.what());
    return 1;
  }
  return 0;
}
