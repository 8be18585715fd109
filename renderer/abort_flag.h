#pragma once
// Aborting a frame from another thread (docs/design.md section 5): the fine render thread is
// stopped the moment the user moves again. Decoders poll a std::atomic<bool> at one tree level
// only.

namespace octopoint {

// The tree level at which a decoder polls its abort flag: at most 8^3 = 512 polls a frame, each a
// relaxed load, and a subtree below it is small enough to finish well within the latency target.
inline constexpr int kAbortCheckLevel = 3;

}  // namespace octopoint
