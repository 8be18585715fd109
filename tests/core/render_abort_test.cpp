// A frame can be aborted from outside through the flag the decoder polls at tree level 3.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>

#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

std::size_t coveredPixels(const Framebuffer& frame) {
  return static_cast<std::size_t>(
      std::count_if(frame.pixels().begin(), frame.pixels().end(),
                    [](std::uint32_t word) { return word != Framebuffer::kEmpty; }));
}

class RenderAbort : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelIssue issue;
    model_ = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    ASSERT_TRUE(model_.has_value()) << describe(issue.error);
    ASSERT_EQ(buildFrameSetup(Camera{}, model_->finestLevel().depth, kDefaultFractionBits, &setup_),
              CameraError::kNone);
  }
  std::optional<ModelView> model_;
  FrameSetup setup_;
  Framebuffer frame_{320, 240};
};

TEST_F(RenderAbort, EveryVariantCompletesAFrameWhenTheFlagStaysClear) {
  for (const VariantInfo& info : allVariants()) {
    const std::atomic<bool> abort{false};
    frame_.clear();
    EXPECT_TRUE(renderLevel(info.variant, model_->finestLevel(), setup_, frame_, &abort))
        << info.name;
    EXPECT_GT(coveredPixels(frame_), 10000u) << info.name;
  }
}

TEST_F(RenderAbort, EveryVariantStopsAtOnceWhenTheFlagIsAlreadySet) {
  for (const VariantInfo& info : allVariants()) {
    const std::atomic<bool> abort{true};
    frame_.clear();
    EXPECT_FALSE(renderLevel(info.variant, model_->finestLevel(), setup_, frame_, &abort))
        << info.name;
    EXPECT_EQ(coveredPixels(frame_), 0u) << info.name << ": drew before its first poll";
  }
}

}  // namespace
}  // namespace octopoint
