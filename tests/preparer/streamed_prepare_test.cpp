// The streamed preparer (codegen/streamed_prepare.h) against the in-memory reference pipeline (the
// preparer as it was before it streamed: voxelize each depth, one palette, encode), and against
// itself across memory budgets and thread counts: the same bytes every time. Also the streamed
// PCD/PLY reader against PCL's, and the streamed intensity percentiles against sorting.

#include "codegen/streamed_prepare.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "codegen/bin_voxelizer.h"
#include "codegen/cube_fit.h"
#include "codegen/intensity_grey.h"
#include "codegen/model_writer.h"
#include "codegen/octree_encoder.h"
#include "codegen/palette.h"
#include "codegen/point_source.h"
#include "codegen/prepare.h"
#include "codegen/sample_reach.h"
#include "codegen/scan_header_check.h"
#include "codegen/scan_loader.h"
#include "codegen/voxelizer.h"
#include "tests/support/synthetic_scans.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// The preparer as it was before it streamed, kept here as the oracle (with the sample reaches it
// measures since).
std::vector<std::uint8_t> referenceImage(const Scan& full_scan, const PrepareOptions& options) {
  const Scan scan = modelPoints(full_scan, "reference", options);
  const CubeFit fit = fitCube(scan.positions, "reference");
  std::vector<VoxelSet> sets;
  for (int depth : options.depths) sets.push_back(voxelize(scan, fit, depth));
  if (options.greyscale) {
    for (VoxelSet& set : sets) {
      for (Rgb8& colour : set.colours) colour = toGrey(colour);
    }
  }
  const Palette palette = Palette::build(sets.back().colours, options.palette_colours);
  PreparedModel model;
  model.name = options.name;
  model.cube_edge_pm = cubeEdgePicometres(fit, options.metres_per_scan_unit, "reference");
  model.cube = cubePlacement(fit, options.axes == ScanAxes::kYUp);
  model.synthetic_colour = scan.shading == ScanShading::kNone && !options.greyscale;
  model.palette = palette.colours();
  for (const VoxelSet& set : sets) {
    PreparedLevel level;
    level.depth = set.depth;
    level.nodes = encodeOctree(set.keys, set.depth);
    for (const Rgb8& colour : set.colours) level.leaves.push_back(palette.indexOf(colour));
    model.levels.push_back(std::move(level));
  }
  // Each level's sample reach, as the preparer measures it (format version 6).
  recordSampleReaches(model);
  return serializeModel(model);
}

PrepareOptions optionsWith(std::vector<int> depths) {
  PrepareOptions options;
  options.name = "m";
  options.depths = std::move(depths);
  return options;
}

std::vector<std::uint8_t> streamedImage(const PointSource& source, const PrepareOptions& options,
                                        std::uint64_t memory_bytes, unsigned threads,
                                        PrepareSummary* summary = nullptr) {
  StreamOptions stream;
  stream.memory_bytes = memory_bytes;
  stream.threads = threads;
  return serializeModel(prepareFromSource(source, "test", options, stream, summary));
}

// A cloud where a third of the points crowd into a tiny corner, so that one bin holds far more
// than a thread's share of a small budget and must be binned again.
Scan clusteredCloud(std::size_t count, std::uint32_t seed) {
  Scan scan = testing::randomCloud(count, seed);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> near(0.0f, 0.004f);
  for (std::size_t i = 0; i < count / 3; ++i)
    scan.positions[i] = {near(random), near(random), near(random)};
  return scan;
}

TEST(StreamedPrepare, MatchesTheInMemoryReferenceForEveryKindOfScan) {
  Scan grey_free = testing::colouredSphere(20000, 3);
  grey_free.colours.clear();
  grey_free.shading = ScanShading::kNone;  // depth shade
  const Scan scans[] = {testing::colouredSphere(30000, 1), testing::randomCloud(40000, 2),
                        grey_free, testing::faceLikeHeightField(150), clusteredCloud(30000, 4)};
  const std::vector<std::vector<int>> depth_lists = {{7, 8}, {1}, {1, 4, 9}, {2, 12}, {16}};
  for (const Scan& scan : scans) {
    for (const auto& depths : depth_lists) {
      PrepareOptions options = optionsWith(depths);
      EXPECT_EQ(serializeModel(prepareModel(scan, "scan", options)), referenceImage(scan, options))
          << "depths " << depths.front() << ".." << depths.back() << ", " << scan.positions.size()
          << " points";
    }
  }
}

TEST(StreamedPrepare, MatchesTheReferenceWithCropAxesGreyscaleAndFewColours) {
  const Scan scan = testing::randomCloud(50000, 9);
  PrepareOptions options = optionsWith({5, 9});
  options.crop = CropBox{{0.1f, 0.2f, 0.0f}, {0.9f, 0.7f, 0.6f}};
  options.axes = ScanAxes::kYUp;
  options.greyscale = true;
  options.palette_colours = 17;
  options.metres_per_scan_unit = 0.01;
  const auto reference = referenceImage(scan, options);
  EXPECT_EQ(serializeModel(prepareModel(scan, "scan", options)), reference);
  // The same through the streamed path, which crops and turns the points itself.
  EXPECT_EQ(streamedImage(*memorySource(scan), options, 1 << 20, 2), reference);
}

TEST(StreamedPrepare, OutputIsTheSameWhateverTheMemoryBudgetAndThreadCount) {
  const Scan scan = clusteredCloud(120000, 5);
  const PrepareOptions options = optionsWith({3, 8, 11});
  const auto reference = referenceImage(scan, options);
  const auto source = memorySource(scan);
  for (std::uint64_t memory : {std::uint64_t{1}, std::uint64_t{200} << 10, std::uint64_t{3} << 20,
                               std::uint64_t{1} << 30}) {
    for (unsigned threads : {1u, 2u, 5u}) {
      PrepareSummary summary;
      EXPECT_EQ(streamedImage(*source, options, memory, threads, &summary), reference)
          << memory << " bytes, " << threads << " threads";
      // The small budgets must really have gone to disk, or this test would not test spilling.
      if (memory <= (std::uint64_t{200} << 10)) {
        EXPECT_GT(summary.spilled_bytes, 0u) << memory;
      }
      if (memory == (std::uint64_t{1} << 30)) {
        EXPECT_EQ(summary.spilled_bytes, 0u);
      }
    }
  }
}

class StreamedFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("octopoint_streamed_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Prepares `path` through the streamed reader and through PCL; both must give the same model.
  void expectSameAsPcl(const fs::path& path, bool streamed_expected) {
    const auto source = openPointSource(path);
    EXPECT_EQ(source->info().streamed, streamed_expected) << path;
    PrepareOptions options = optionsWith({4, 9});
    EXPECT_EQ(streamedImage(*source, options, 1 << 20, 3),
              serializeModel(prepareModel(loadScan(path), "pcl", options)))
        << path;
  }

  fs::path dir_;
};

template <typename PointT>
pcl::PointCloud<PointT> cloudWithHoles(std::size_t count) {
  pcl::PointCloud<PointT> cloud;
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> byte(0, 255);
  for (std::size_t i = 0; i < count; ++i) {
    PointT p;
    p.x = unit(random);
    p.y = unit(random);
    p.z = i % 97 == 5 ? std::numeric_limits<float>::quiet_NaN() : unit(random);
    if constexpr (requires { p.intensity; }) p.intensity = 1000 * unit(random) * unit(random);
    if constexpr (requires { p.r; }) {
      p.r = static_cast<std::uint8_t>(byte(random));
      p.g = static_cast<std::uint8_t>(byte(random));
      p.b = static_cast<std::uint8_t>(byte(random));
    }
    cloud.push_back(p);
  }
  return cloud;
}

TEST_F(StreamedFileTest, BinaryPcdAndPlyStreamToTheSameModelAsPclReadsThem) {
  const auto xyz = cloudWithHoles<pcl::PointXYZ>(30000);
  const auto rgb = cloudWithHoles<pcl::PointXYZRGB>(30000);
  const auto rgba = cloudWithHoles<pcl::PointXYZRGBA>(30000);
  const auto intensity = cloudWithHoles<pcl::PointXYZI>(30000);
  auto save = [&](const auto& cloud, const std::string& name, bool binary) {
    const fs::path path = dir_ / name;
    const bool ply = path.extension() == ".ply";
    const int result = ply ? pcl::io::savePLYFile(path.string(), cloud, binary)
                           : (binary ? pcl::io::savePCDFileBinary(path.string(), cloud)
                                     : pcl::io::savePCDFileBinaryCompressed(path.string(), cloud));
    EXPECT_EQ(result, 0);
    return path;
  };
  for (const char* extension : {".pcd", ".ply"}) {
    expectSameAsPcl(save(xyz, std::string("xyz") + extension, true), true);
    expectSameAsPcl(save(rgb, std::string("rgb") + extension, true), true);
    expectSameAsPcl(save(rgba, std::string("rgba") + extension, true), true);
    expectSameAsPcl(save(intensity, std::string("intensity") + extension, true), true);
  }
  // Compressed PCD and ascii PLY go through PCL, the same way.
  expectSameAsPcl(save(rgb, "compressed.pcd", false), false);
  expectSameAsPcl(save(intensity, "ascii.ply", false), false);
}

// A binary PLY of PCL's as big-endian: the header's format word changed and every scalar of every
// element (PCL writes a camera element after the vertices) byte-swapped.
fs::path bigEndianCopy(const fs::path& little, const fs::path& big) {
  std::ifstream in(little, std::ios::binary);
  std::string header;
  std::vector<std::pair<std::uint64_t, std::vector<std::uint64_t>>> elements;  // count, sizes
  for (std::string line; std::getline(in, line) && line != "end_header";) {
    std::istringstream words(line);
    std::string keyword, type;
    words >> keyword >> type;
    if (keyword == "format") line = "format binary_big_endian 1.0";
    if (keyword == "element") elements.push_back({std::stoull(line.substr(line.rfind(' '))), {}});
    if (keyword == "property") elements.back().second.push_back(plyTypeBytes(type));
    header += line + "\n";
  }
  // Read by size: GCC 12 warns of a null dereference in istreambuf_iterator here (unity build).
  const std::streampos body_start = in.tellg();
  in.seekg(0, std::ios::end);
  std::string body(static_cast<std::size_t>(in.tellg() - body_start), '\0');
  in.seekg(body_start);
  in.read(body.data(), static_cast<std::streamsize>(body.size()));
  std::size_t at = 0;
  for (const auto& [count, sizes] : elements) {
    for (std::uint64_t item = 0; item < count; ++item) {
      for (const std::uint64_t size : sizes) {
        std::reverse(body.begin() + static_cast<std::ptrdiff_t>(at),
                     body.begin() + static_cast<std::ptrdiff_t>(at + size));
        at += size;
      }
    }
  }
  EXPECT_EQ(at, body.size());
  std::ofstream(big, std::ios::binary) << header << "end_header\n" << body;
  return big;
}

TEST_F(StreamedFileTest, BigEndianPlyStreamsToTheSameModelAsPclReadsIt) {
  // PCL reads big-endian PLY value by value: a 1 GiB file took 23 s and 3.5 GB whole.
  auto save = [&](const auto& cloud, const std::string& name) {
    const fs::path path = dir_ / (name + "_little.ply");
    EXPECT_EQ(pcl::io::savePLYFile(path.string(), cloud, true), 0);
    return bigEndianCopy(path, dir_ / (name + "_big.ply"));
  };
  expectSameAsPcl(save(cloudWithHoles<pcl::PointXYZ>(30000), "xyz"), true);
  expectSameAsPcl(save(cloudWithHoles<pcl::PointXYZRGB>(30000), "rgb"), true);
  expectSameAsPcl(save(cloudWithHoles<pcl::PointXYZI>(30000), "intensity"), true);
}

TEST(IntensityPercentiles, FindTheSameValuesAsSorting) {
  std::mt19937 random(3);
  std::normal_distribution<float> normal(0.0f, 300.0f);
  for (std::size_t count : {1u, 2u, 7u, 100u, 5000u, 200000u}) {
    std::vector<float> values;
    for (std::size_t i = 0; i < count; ++i)
      values.push_back(i % 13 == 0 ? std::round(normal(random)) : normal(random));
    if (count > 10) {
      values[3] = -0.0f;
      values[4] = 0.0f;
      values[5] = std::numeric_limits<float>::quiet_NaN();
      values[6] = std::numeric_limits<float>::infinity();
      values[7] = 5.0f;
      values[8] = 5.0f;
    }
    IntensityPercentiles coarse;
    for (float v : values) coarse.addCoarse(v);
    coarse.finishCoarse();
    IntensityPercentiles fine_a = coarse.forFinePass(), fine_b = coarse.forFinePass();
    for (std::size_t i = 0; i < values.size(); ++i) (i % 2 ? fine_a : fine_b).addFine(values[i]);
    coarse.merge(fine_a);
    coarse.merge(fine_b);
    const IntensityRange range = coarse.range();
    std::vector<float> finite;
    for (float v : values) {
      if (std::isfinite(v)) finite.push_back(v);
    }
    std::sort(finite.begin(), finite.end());
    EXPECT_EQ(range.low, finite[quantileRank(finite.size(), kLowIntensityQuantile)]) << count;
    EXPECT_EQ(range.high, finite[quantileRank(finite.size(), kHighIntensityQuantile)]) << count;
  }
}

TEST(MortonKey, TheMagicNumberSplitMatchesBitByBitInterleaving) {
  std::mt19937 random(1);
  for (int depth = 1; depth <= 21; ++depth) {
    std::uniform_int_distribution<std::uint32_t> index(0, (1u << depth) - 1);
    for (int i = 0; i < 200; ++i) {
      const std::uint32_t x = index(random), y = index(random), z = index(random);
      std::uint64_t expected = 0;
      for (int bit = depth - 1; bit >= 0; --bit) {
        expected =
            expected << 3 | ((x >> bit) & 1u) << 2 | ((y >> bit) & 1u) << 1 | ((z >> bit) & 1u);
      }
      ASSERT_EQ(mortonKey(x, y, z, depth), expected) << depth;
    }
  }
}

TEST(OctreeEncoder, LeafKeysComeBackOutOfTheStream) {
  std::mt19937 random(2);
  std::uniform_int_distribution<std::uint64_t> key(0, (std::uint64_t{1} << 30) - 1);
  std::vector<std::uint64_t> keys;
  for (int i = 0; i < 5000; ++i) keys.push_back(key(random));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  EXPECT_EQ(decodeLeafKeys(encodeOctree(keys, 10), 10), keys);
}

}  // namespace
}  // namespace octopoint::prepare
