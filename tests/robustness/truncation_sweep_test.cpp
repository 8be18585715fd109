// Every prefix of a real model is refused, and refused for the right reason, without reading a byte
// past the prefix. The model is the default one (a Kinect scan, embedded in the build) written as
// the `.oct` file octopoint-prepare makes. Under AddressSanitizer (the asan preset) the bytes past
// each prefix are poisoned, so a read beyond it is reported even though the buffer goes on.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/models.h"
#include "tests/support/model_images.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#define OCTOPOINT_POISON(address, size) ASAN_POISON_MEMORY_REGION(address, size)
#define OCTOPOINT_UNPOISON(address, size) ASAN_UNPOISON_MEMORY_REGION(address, size)
#else
#define OCTOPOINT_POISON(address, size) ((void)(address), (void)(size))
#define OCTOPOINT_UNPOISON(address, size) ((void)(address), (void)(size))
#endif

namespace octopoint {
namespace {

// A buffer whose first `readable` bytes are the only ones that may be read: it grows one byte at
// a time, so every prefix length costs one unpoisoning.
class GrowingPrefix {
 public:
  explicit GrowingPrefix(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {
    OCTOPOINT_POISON(bytes_.data(), bytes_.size());
  }
  ~GrowingPrefix() { OCTOPOINT_UNPOISON(bytes_.data(), bytes_.size()); }
  GrowingPrefix(const GrowingPrefix&) = delete;
  GrowingPrefix& operator=(const GrowingPrefix&) = delete;

  std::size_t fullSize() const { return bytes_.size(); }
  // The first `length` bytes, readable; lengths must come in increasing order.
  std::span<const std::uint8_t> prefix(std::size_t length) {
    OCTOPOINT_UNPOISON(bytes_.data(), length);
    return {bytes_.data(), length};
  }

 private:
  std::vector<std::uint8_t> bytes_;
};

const std::vector<std::uint8_t>& truncatedModelSource() {
  static const std::vector<std::uint8_t> image = fuzzing::octImage(*models::defaultModel());
  return image;
}

TEST(TruncationSweep, TheWholeDefaultModelValidates) {
  ModelIssue issue;
  const auto model = ModelView::fromBytes(truncatedModelSource(), &issue);
  ASSERT_TRUE(model.has_value()) << describe(issue.error) << " at byte " << issue.offset;
  EXPECT_EQ(model->levelCount(), models::defaultModel()->level_count);
}

TEST(TruncationSweep, EveryPrefixOfTheDefaultModelIsRefused) {
  const std::vector<std::uint8_t>& image = truncatedModelSource();
  // Version 6: 788 header bytes, 6 per normal palette entry (count at byte 18), the cube's
  // placement (40), 12 per level row.
  ASSERT_EQ(image[4], 6);
  const std::size_t normal_count = image[18] | std::size_t{image[19]} << 8;
  const std::size_t table_end = 788 + 6 * normal_count + 40 + 12 * std::size_t{image[6]};
  GrowingPrefix buffer(image);
  std::size_t accepted = 0;
  for (std::size_t length = 0; length < buffer.fullSize(); ++length) {
    ModelIssue issue;
    const bool valid = ModelView::fromBytes(buffer.prefix(length), &issue).has_value();
    const ModelError expected =
        length < table_end ? ModelError::kTruncatedHeader : ModelError::kSizeMismatch;
    if (valid || issue.error != expected) {
      ++accepted;
      ADD_FAILURE() << "prefix of " << length << " bytes: " << describe(issue.error);
      if (accepted > 10) return;
    }
  }
}

// The stream walk on its own, for every level: prefixes of the node bytes (with all the leaves)
// and of the leaves (with all the node bytes) are refused. Each part is copied alone into its own
// poisoned buffer, so a read past it cannot land in the next part. Every walk costs the length
// of the stream, so not every prefix is tried (see swept).
bool swept(std::size_t length, std::size_t size, bool every_length) {
  constexpr std::size_t kStride = 61;        // a prime: cuts fall at every position within a node
  constexpr std::size_t kNearTheEnd = 1024;  // the cuts that leave the walk the least to find
  return every_length || length % kStride == 0 || length + kNearTheEnd >= size;
}

TEST(TruncationSweep, PrefixesOfEachStreamAreRefused) {
  const EmbeddedModel& model = *models::defaultModel();
  for (int i = 0; i < model.level_count; ++i) {
    const EmbeddedLevel& level = model.levels[i];
    const std::vector<std::uint8_t> nodes(level.nodes, level.nodes + level.node_bytes);
    const std::vector<std::uint8_t> leaves(level.leaves, level.leaves + level.leaf_count);
    GrowingPrefix node_prefixes(nodes);
    GrowingPrefix leaf_prefixes(leaves);
    int failures = 0;
    // Every node prefix of the coarsest level; a sample of the others.
    for (std::size_t length = 0; length < nodes.size() && failures < 10; ++length) {
      if (!swept(length, nodes.size(), i == 0)) continue;
      const LevelView view{level.depth, node_prefixes.prefix(length), leaves};
      const ModelError error = validateLevelStream(view, model.palette_count).error;
      const bool clean = error == ModelError::kStreamTruncated ||
                         error == ModelError::kImplausibleLevelSize ||
                         (length == 0 && error == ModelError::kEmptyLevel);
      if (!clean) {
        ++failures;
        ADD_FAILURE() << "depth " << level.depth << ", " << length
                      << " node bytes: " << describe(error);
      }
    }
    for (std::size_t length = 0; length < leaves.size() && failures < 10; ++length) {
      if (!swept(length, leaves.size(), false)) continue;
      const LevelView view{level.depth, nodes, leaf_prefixes.prefix(length)};
      const ModelError error = validateLevelStream(view, model.palette_count).error;
      const bool clean = error == ModelError::kLeafCountMismatch ||
                         error == ModelError::kImplausibleLevelSize ||
                         (length == 0 && error == ModelError::kEmptyLevel);
      if (!clean) {
        ++failures;
        ADD_FAILURE() << "depth " << level.depth << ", " << length
                      << " leaves: " << describe(error);
      }
    }
  }
}

// The smaller real models of the fuzzers' seed corpus are valid too (else they seed nothing).
TEST(TruncationSweep, TheCoarsenedSeedModelsValidate) {
  const EmbeddedModel& model = *models::defaultModel();
  for (int depth = 1; depth <= model.levels[model.level_count - 1].depth; ++depth) {
    const std::vector<std::uint8_t> image = fuzzing::coarsenedOctImage(model, depth);
    ModelIssue issue;
    EXPECT_TRUE(ModelView::fromBytes(image, &issue).has_value())
        << "depth " << depth << ": " << describe(issue.error);
  }
}

}  // namespace
}  // namespace octopoint
