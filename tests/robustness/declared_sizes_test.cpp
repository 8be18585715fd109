// ModelView::checkDeclaredSizes, what octopoint-render and octopoint-view check of a model file
// before reading its body: from the header and level table alone it must refuse exactly what
// fromBytes refuses for the header and table, with the same issue, and never refuse a model that
// fromBytes accepts. Checked on the default model's `.oct` image (a real scan) with every header
// and level table byte changed in several ways, and with the file's size wrong by any amount.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <set>
#include <span>
#include <vector>

#include "octopoint/model.h"
#include "octopoint/models.h"
#include "tests/support/model_images.h"

namespace octopoint {
namespace {

// The largest header and level table: version 2 with 255 normals and 8 levels.
constexpr std::size_t kLargestHead = format::v2::kFixedHeaderBytes +
                                     format::v2::kNormalEntryBytes * format::kMaxNormals +
                                     format::kLevelRowBytes * format::kMaxLevels;

const std::vector<std::uint8_t>& defaultModelImage() {
  static const std::vector<std::uint8_t> image = fuzzing::octImage(*models::defaultModel());
  return image;
}

std::span<const std::uint8_t> headOf(const std::vector<std::uint8_t>& image) {
  return {image.data(), std::min(image.size(), kLargestHead)};
}

// The errors fromBytes finds without reading a level's data.
bool isHeaderError(ModelError error) {
  static const std::set<ModelError> kHeaderErrors = {ModelError::kTruncatedHeader,
                                                     ModelError::kBadMagic,
                                                     ModelError::kUnsupportedVersion,
                                                     ModelError::kBadLevelCount,
                                                     ModelError::kBadReservedField,
                                                     ModelError::kBadPaletteCount,
                                                     ModelError::kBadDepth,
                                                     ModelError::kDepthsNotAscending,
                                                     ModelError::kSizeMismatch,
                                                     ModelError::kEmptyLevel,
                                                     ModelError::kImplausibleLevelSize,
                                                     ModelError::kBadNormalCount,
                                                     ModelError::kBadNormalVector};
  return kHeaderErrors.count(error) != 0;
}

void expectSameIssue(const ModelIssue& a, const ModelIssue& b) {
  EXPECT_EQ(a.error, b.error) << describe(a.error) << " / " << describe(b.error);
  EXPECT_EQ(a.offset, b.offset);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.offset_in_file, b.offset_in_file);
}

// checkDeclaredSizes on the image's head agrees with fromBytes on the whole image.
void expectAgreement(const std::vector<std::uint8_t>& image) {
  ModelIssue whole;
  const bool valid = ModelView::fromBytes(image, &whole).has_value();
  ModelIssue head;
  const bool head_valid = ModelView::checkDeclaredSizes(headOf(image), image.size(), &head);
  if (valid) {
    EXPECT_TRUE(head_valid) << "refused a valid model: " << describe(head.error);
  } else if (isHeaderError(whole.error)) {
    EXPECT_FALSE(head_valid) << "missed " << describe(whole.error) << " at " << whole.offset;
    expectSameIssue(head, whole);
  }
  // Else the whole validation met a level's data first (it walks level by level), and the head
  // may refuse a later level's row: refused either way.
}

TEST(DeclaredSizes, TheDefaultModelPasses) {
  ModelIssue issue;
  EXPECT_TRUE(ModelView::checkDeclaredSizes(headOf(defaultModelImage()), defaultModelImage().size(),
                                            &issue))
      << describe(issue.error);
}

TEST(DeclaredSizes, EveryHeaderAndTableByteChangedAgreesWithTheWholeValidation) {
  const std::vector<std::uint8_t>& original = defaultModelImage();
  const std::size_t normals = original[18] | original[19] << 8;
  const std::size_t table_end = format::v2::kFixedHeaderBytes +
                                format::v2::kNormalEntryBytes * normals +
                                format::kLevelRowBytes * original[6];
  std::vector<std::uint8_t> image = original;
  for (std::size_t at = 0; at < table_end; ++at) {
    for (const int change : {0, 1, 0xff, original[at] ^ 1, original[at] + 1, original[at] ^ 0x80}) {
      image[at] = static_cast<std::uint8_t>(change);
      SCOPED_TRACE("byte " + std::to_string(at) + " = " + std::to_string(image[at]));
      expectAgreement(image);
      if (::testing::Test::HasFailure()) return;
    }
    image[at] = original[at];
  }
}

TEST(DeclaredSizes, AFileOfAnyOtherSizeIsRefusedAsADeclaredSizeMismatch) {
  const std::vector<std::uint8_t>& original = defaultModelImage();
  for (const std::size_t extra : {1u, 2u, 100u, 4096u}) {
    std::vector<std::uint8_t> longer = original;
    longer.resize(original.size() + extra);
    expectAgreement(longer);
  }
  for (const std::uint64_t size :
       {std::uint64_t{original.size() - 1}, std::uint64_t{original.size() / 2},
        std::uint64_t{kLargestHead + 1}, std::uint64_t{900'000'000}, std::uint64_t{1} << 30,
        std::uint64_t{1} << 40}) {
    ModelIssue issue;
    EXPECT_FALSE(ModelView::checkDeclaredSizes(headOf(original), size, &issue)) << size;
    EXPECT_EQ(issue.error, ModelError::kSizeMismatch) << size;
  }
  for (std::size_t length = 0; length < original.size(); length += 997) {
    const std::vector<std::uint8_t> cut(original.begin(),
                                        original.begin() + static_cast<std::ptrdiff_t>(length));
    expectAgreement(cut);
  }
}

}  // namespace
}  // namespace octopoint
