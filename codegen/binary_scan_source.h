#pragma once
// Streaming binary PCD and binary little-endian PLY files without PCL (see the .cpp for which
// layouts qualify).

#include <cstdint>
#include <filesystem>
#include <memory>

#include "codegen/point_source.h"

namespace octopoint::prepare {

// A source for a file whose header checkPcdHeader / checkPlyHeader has accepted, or null when its
// layout is not one this reader streams (then PCL reads it).
std::unique_ptr<PointSource> openBinaryScanSource(const std::filesystem::path& path,
                                                  std::uint64_t file_size, bool is_ply);

}  // namespace octopoint::prepare
