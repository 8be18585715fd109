#pragma once
// What the preparer has made of a scan, before it is written out as a `.oct` file or C++ sources.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace octopoint::prepare {

using Rgb8 = std::array<std::uint8_t, 3>;

struct PreparedLevel {
  int depth = 0;
  std::vector<std::uint8_t> nodes;   // depth-first child mask bytes (renderer/model_format.h)
  std::vector<std::uint8_t> leaves;  // one palette index per leaf, depth-first
  // What visibility pruning did (when it ran): the level before it, and the time it took.
  std::size_t voxels_before_pruning = 0;
  std::size_t bytes_before_pruning = 0;  // node bytes + colour bytes
  double pruning_seconds = 0;
};

struct PreparedModel {
  std::string name;                // a C++ identifier
  std::string source_description;  // where it came from, for the generated comments
  std::uint32_t cube_edge_um = 0;
  std::vector<Rgb8> palette;       // 1..256 colours
  std::vector<PreparedLevel> levels;  // depths strictly ascending
  std::vector<int> sparse_depths_dropped;  // asked for, but finer than the scan samples densely
};

}  // namespace octopoint::prepare
