#pragma once
// What the preparer has made of a scan, before it is written out as a `.oct` file or C++ sources.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace octopoint::prepare {

using Rgb8 = std::array<std::uint8_t, 3>;

struct PreparedLevel {
  int depth = 0;
  std::vector<std::uint8_t> nodes;   // depth-first child mask bytes (renderer/model_format.h)
  std::vector<std::uint8_t> leaves;  // one palette index per leaf, depth-first
};

struct PreparedModel {
  std::string name;                // a C++ identifier
  std::string source_description;  // where it came from, for the generated comments
  std::uint32_t cube_edge_um = 0;
  std::vector<Rgb8> palette;       // 1..256 colours
  std::vector<PreparedLevel> levels;  // depths strictly ascending
};

}  // namespace octopoint::prepare
