#pragma once
// Helpers for the chunked-format and progressive-model tests: an independent reference for what a
// progressive model must draw, and a way to re-seal a file after a test has altered it.

#include <cstdint>
#include <span>
#include <vector>

#include "codegen/prepared_model.h"
#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/progressive.h"
#include "octopoint/render.h"
#include "tests/support/model_images.h"

namespace octopoint::testing {

using Bytes = std::vector<std::uint8_t>;

// What a progressive model holding some chunks must draw, worked out from the whole-model streams
// of each depth (`levels`: the base's stream first, then one per chunked level, as the preparer
// wrote them) and only the model's chunk states: a voxel of level j is drawn when its level-j
// region is held (the base always is) and, below the finest level the view draws, its level-(j+1)
// region is not. Each level's voxels so chosen are encoded as one stream and drawn by `variant`
// with the frame's set-up for that depth (z keys as the finest level drawn).
Framebuffer referenceFrame(const ProgressiveModel& model,
                           const std::vector<prepare::PreparedLevel>& levels, const Camera& camera,
                           Variant variant);

// The finest of `levels` (in depth order) at most `depth` deep, or nullptr: the whole-model stream
// a complete model draws for a view that wants `depth`.
const prepare::PreparedLevel* finestLevelAtMost(const std::vector<prepare::PreparedLevel>& levels,
                                                int depth);

// The base and chunked levels' whole-model streams of a chunked image written from `prepared`:
// the base decoded from the image's head, then the prepared levels the chunked levels hold.
std::vector<prepare::PreparedLevel> levelStreams(std::span<const std::uint8_t> image,
                                                 const prepare::PreparedModel& prepared);

// Recomputes every CRC of a chunked image (tests/support/model_images.h).
inline void reseal(Bytes& image) { fuzzing::resealChunked(image); }

// Feeds a model every record table, then every chunk in `order` (indices into the chunk list in
// file order); returns the chunk items in file order.
std::vector<FetchItem> allChunkItems(const ProgressiveModel& model);
void feedTables(ProgressiveModel& model, std::span<const std::uint8_t> image);
void feed(ProgressiveModel& model, std::span<const std::uint8_t> image, const FetchItem& item);

bool sameFrame(const Framebuffer& a, const Framebuffer& b);

// A camera of `width` x `height` pixels turned by `yaw` and `pitch` degrees at `zoom`, panned by
// whole pixels.
Camera makeCamera(int yaw, int pitch, double zoom, int width, int height, int pan_x = 0,
                  int pan_y = 0);

}  // namespace octopoint::testing
