#pragma once
// What the preparer has made of a scan, before it is written out as a `.oct` file or C++ sources.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/model.h"

namespace octopoint::prepare {

using Rgb8 = std::array<std::uint8_t, 3>;

struct PreparedLevel {
  int depth = 0;
  std::vector<std::uint8_t> nodes;      // depth-first child mask bytes (octopoint/model.h)
  std::vector<std::uint8_t> leaves;     // one palette index per leaf, depth-first
  std::vector<std::uint8_t> normals{};  // one normal palette index per leaf, or empty (no normals)
  // How wide its splats are drawn, in sixteenths of a voxel footprint (format version 6's level
  // table): measured against the next coarser level (codegen/sample_reach.h, recordSampleReaches).
  std::uint8_t sample_reach = format::kOneSampleReachQ4;
  // What visibility pruning did (when it ran): the level before it, and the time it took.
  std::size_t voxels_before_pruning = 0;
  std::size_t bytes_before_pruning = 0;  // node bytes + colour bytes
  double pruning_seconds = 0;
};

struct PreparedModel {
  std::string name;                // a C++ identifier
  std::string source_description;  // where it came from, for the generated comments
  std::uint64_t cube_edge_pm = 0;  // the cube's edge in picometres (octopoint/model.h)
  CubePlacement cube;              // where the cube lies in the scan (octopoint/model.h)
  std::vector<Rgb8> palette;       // 1..256 colours
  bool synthetic_colour = false;   // the scan had no colour: the palette is a depth shade
  // Unit vectors in Q1.14, 1..255 of them when the levels carry normals, else none.
  std::vector<std::array<std::int16_t, 3>> normal_palette;
  // With normals: how they were made, and the angle between the finest level's voxel normals and
  // the palette entries they are stored as.
  int normal_neighbours = 0;  // k of the k-NN PCA
  bool normals_from_integral_images = false;
  double normal_seconds = 0;  // estimation and quantization
  double normal_error_mean_deg = 0;
  double normal_error_max_deg = 0;
  std::vector<PreparedLevel> levels;       // depths strictly ascending
  std::vector<int> sparse_depths_dropped;  // asked for, but finer than the scan samples densely
  // The levels' sample_reach measured on these levels already (the default depth cut measures
  // them): recordSampleReaches need not measure again. Pruning, which changes levels, clears it.
  bool sample_reaches_measured = false;
};

}  // namespace octopoint::prepare
