#pragma once
// The shape of a model compiled into an app: plain aggregates of pointers to const arrays, so the
// preparer's generated sources initialise them at compile time (no constructor runs, no file I/O).
// Use it through ModelView::fromEmbedded, which validates it once. The fields mean what the same
// fields of a version 2 `.oct` file mean (renderer/model_format.h).

#include <cstdint>

namespace octopoint {

struct EmbeddedLevel {
  std::uint8_t depth;
  const std::uint8_t* nodes;    // depth-first child mask bytes
  std::uint32_t node_bytes;
  const std::uint8_t* leaves;   // palette index per leaf
  std::uint32_t leaf_count;
  const std::uint8_t* normals = nullptr;  // normal index per leaf; nullptr: no normals
};

struct EmbeddedModel {
  const char* name;
  // The format version the generated arrays follow (format::kVersion2); a source generated for
  // another layout fails to compile or is refused (kUnsupportedVersion).
  std::uint16_t format_version;
  std::uint8_t flags;            // format::v2::kFlag*
  std::uint64_t cube_edge_pm;    // the model cube's edge in picometres; 0: not recorded
  std::uint16_t palette_count;
  const std::uint8_t* palette_rgb;  // 256 x RGB888
  std::uint16_t normal_count;       // 0 without normals
  const std::int16_t* normal_xyz;   // normal_count x (x, y, z) in Q1.14, or nullptr
  std::uint8_t level_count;
  const EmbeddedLevel* levels;      // depths strictly ascending
};

}  // namespace octopoint
