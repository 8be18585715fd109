#pragma once
// The shape of a model compiled into an app: plain aggregates of pointers to const arrays, so the
// preparer's generated sources initialise them at compile time (no constructor runs, no file I/O).
// Use it through ModelView::fromEmbedded, which validates it once.

#include <cstdint>

namespace octopoint {

struct EmbeddedLevel {
  std::uint8_t depth;
  const std::uint8_t* nodes;   // depth-first child mask bytes
  std::uint32_t node_bytes;
  const std::uint8_t* leaves;  // palette index per leaf
  std::uint32_t leaf_count;
};

struct EmbeddedModel {
  const char* name;
  std::uint32_t cube_edge_um;
  std::uint16_t palette_count;
  const std::uint8_t* palette_rgb;  // 256 x RGB888
  std::uint8_t level_count;
  const EmbeddedLevel* levels;      // depths strictly ascending
};

}  // namespace octopoint
