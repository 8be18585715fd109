#include "codegen/bin_voxelizer.h"

#include <bit>
#include <cassert>
#include <cstring>

#include "codegen/octree_encoder.h"
#include "codegen/voxelizer.h"

namespace octopoint::prepare {
namespace {

constexpr int kRadixBits = 8;
constexpr std::size_t kRadixBuckets = std::size_t{1} << kRadixBits;

std::uint32_t pack(const Rgb8& c) {
  return std::uint32_t{c[0]} << 16 | std::uint32_t{c[1]} << 8 | c[2];
}

// Sorts `points` by the low `key_bits` bits of their keys (the rest is the node's common prefix):
// least significant digit first, 8 bits a pass, one counting read for all passes, and a pass
// skipped when every key has the same digit there. `scratch` holds as many points. Returns the
// sorted points, which are in `points` or in `scratch`.
std::span<BinnedPoint> radixSort(std::span<BinnedPoint> points, std::span<BinnedPoint> scratch,
                                 int key_bits) {
  const int passes = (key_bits + kRadixBits - 1) / kRadixBits;
  if (passes == 0 || points.size() < 2) return points;
  std::vector<std::array<std::uint64_t, kRadixBuckets>> counts(static_cast<std::size_t>(passes));
  for (auto& c : counts) c.fill(0);
  for (const BinnedPoint& p : points) {
    const std::uint64_t key = p.key();
    for (int pass = 0; pass < passes; ++pass) {
      ++counts[static_cast<std::size_t>(pass)][key >> (kRadixBits * pass) & 0xffu];
    }
  }
  std::span<BinnedPoint> from = points;
  std::span<BinnedPoint> to = scratch.first(points.size());
  for (int pass = 0; pass < passes; ++pass) {
    auto& c = counts[static_cast<std::size_t>(pass)];
    const int shift = kRadixBits * pass;
    if (c[from[0].key() >> shift & 0xffu] == points.size()) continue;  // one digit for all
    std::uint64_t start = 0;
    for (std::uint64_t& count : c) start += std::exchange(count, start);
    for (const BinnedPoint& p : from) to[c[p.key() >> shift & 0xffu]++] = p;
    std::swap(from, to);
  }
  return from;
}

NodeResult emptyNode(const VoxelColouring& colouring) {
  NodeResult node;
  node.levels.resize(colouring.depths.size());
  return node;
}

// The node at `level` from its children at level + 1.
NodeResult joinChildren(int level, std::vector<std::pair<std::uint64_t, NodeResult>>& children,
                        const VoxelColouring& colouring, ColourStore& store) {
  NodeResult node = emptyNode(colouring);
  std::uint8_t mask = 0;
  for (const auto& [prefix, child] : children) {
    node.sum.merge(child.sum);
    mask = static_cast<std::uint8_t>(mask | 1u << (prefix & 7u));
  }
  for (std::size_t i = 0; i < colouring.depths.size(); ++i) {
    const int depth = colouring.depths[i];
    if (depth <= level) continue;
    SubtreePieces& part = node.levels[i];
    part.nodes.push_back({mask});
    if (depth == level + 1) {  // the children are this depth's voxels
      std::uint32_t* colours = store.reserve(children.size());
      for (const auto& [prefix, child] : children)
        *colours++ = colouring.voxelColour(child.sum, prefix, depth);
      part.colours.push_back(store.commit(children.size()));
      continue;
    }
    for (auto& [prefix, child] : children) {
      SubtreePieces& below = child.levels[i];
      for (auto& piece : below.nodes) part.nodes.push_back(std::move(piece));
      for (const auto& piece : below.colours) part.colours.push_back(piece);
    }
  }
  return node;
}

}  // namespace

Rgb8 toGrey(const Rgb8& c) {
  const auto grey = static_cast<std::uint8_t>((77 * c[0] + 150 * c[1] + 29 * c[2] + 128) >> 8);
  return {grey, grey, grey};
}

std::uint32_t VoxelColouring::pointColour(std::uint32_t value) const {
  switch (payload) {
    case Payload::kRgb:
      return value;
    case Payload::kIntensity:
      return 0x010101u * intensityGrey(std::bit_cast<float>(value), intensity);
    case Payload::kNone:
      return 0;
  }
  return 0;
}

std::uint32_t VoxelColouring::voxelColour(const ColourSum& sum, std::uint64_t key,
                                          int depth) const {
  Rgb8 colour{};
  if (payload == Payload::kNone) {
    const int shift = finest() - depth;
    const std::uint8_t grey =
        depthShade(mortonDecode(key, depth)[2], near_z >> shift, far_z >> shift);
    colour = {grey, grey, grey};
  } else {
    for (std::size_t ch = 0; ch < 3; ++ch) {
      colour[ch] =
          static_cast<std::uint8_t>((sum.rgb[ch] + sum.count / 2) / sum.count);  // rounded mean
    }
  }
  return pack(greyscale ? toGrey(colour) : colour);
}

NodeResult voxelizeNode(std::span<BinnedPoint> unsorted, int level, const VoxelColouring& colouring,
                        VoxelizerBuffers& buffers, ColourStore& store) {
  assert(!unsorted.empty());
  const int finest = colouring.finest();
  const std::span<BinnedPoint> points =
      radixSort(unsorted, buffers.scratch.resize(unsorted.size()), 3 * (finest - level));
  NodeResult node = emptyNode(colouring);
  std::vector<std::uint64_t>& keys = buffers.keys;
  keys.clear();
  for (BinnedPoint& p : points) {
    if (colouring.payload != VoxelColouring::Payload::kRgb) {
      p.payload = colouring.pointColour(p.payload);
    }
    node.sum.add(p.payload);
    if (keys.empty() || keys.back() != p.key()) keys.push_back(p.key());
  }
  for (std::size_t i = 0; i < colouring.depths.size(); ++i) {
    const int depth = colouring.depths[i];
    if (depth <= level) continue;
    SubtreePieces& part = node.levels[i];
    // Room for what the finest depth needs (a node byte per voxel at most, on average much
    // less): no copy as they grow.
    std::vector<std::uint8_t>& nodes = part.nodes.emplace_back();
    nodes.reserve(depth == finest ? keys.size() : 0);
    encodeSubtree(keys, level, depth, finest, nodes);
    std::uint32_t* const colours = store.reserve(keys.size());  // at most a voxel per key
    std::size_t voxels = 0;
    const int shift = 3 * (finest - depth);
    ColourSum sum;
    for (std::size_t p = 0; p < points.size(); ++p) {
      sum.add(points[p].payload);
      const std::uint64_t key = points[p].key() >> shift;
      if (p + 1 == points.size() || points[p + 1].key() >> shift != key) {
        colours[voxels++] = colouring.voxelColour(sum, key, depth);
        sum = {};
      }
    }
    part.colours.push_back(store.commit(voxels));
  }
  return node;
}

NodeResult combineNodes(int level, int child_level,
                        std::vector<std::pair<std::uint64_t, NodeResult>> children,
                        const VoxelColouring& colouring, ColourStore& store) {
  assert(child_level > level && !children.empty());
  if (child_level == level + 1) return joinChildren(level, children, colouring, store);
  // Group the descendants by the node at level + 1 they lie in, join each group, then join those.
  const int shift = 3 * (child_level - level - 1);
  std::vector<std::pair<std::uint64_t, NodeResult>> middle;
  for (std::size_t begin = 0; begin < children.size();) {
    const std::uint64_t middle_prefix = children[begin].first >> shift;
    std::size_t end = begin;
    std::vector<std::pair<std::uint64_t, NodeResult>> group;
    while (end < children.size() && children[end].first >> shift == middle_prefix) {
      group.push_back(std::move(children[end++]));
    }
    middle.emplace_back(middle_prefix,
                        combineNodes(level + 1, child_level, std::move(group), colouring, store));
    begin = end;
  }
  return joinChildren(level, middle, colouring, store);
}

}  // namespace octopoint::prepare
