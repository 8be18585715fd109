#pragma once
// How octopoint-view draws a chunked model streaming in (--url): the orbit views and the walk
// frames, each render thread from what the stream holds when it starts a frame.

#include <atomic>
#include <cstdint>

#include "octopoint/http.h"
#include "octopoint/interactive.h"

namespace octopoint {

// Orbit views: the fine frame at the depth the view needs, the coarse one a stored depth coarser;
// an empty frame until the head has arrived. Each render thread draws from its own snapshot of the
// chunks held, taken under the stream's lock for a copy of one byte per chunk, and draws without
// the lock: chunks keep arriving while it draws.
ViewDrawFunction streamDrawer(net::ModelStream& stream, std::uint64_t point_budget);

// Walk frames as octopoint-render --url --eye draws them: the parts held (assembleHeldParts,
// renderer/chunked_assembly.h), each at the depth its distance asks for or the finest held there,
// one after another into the frame. Each render thread assembles its own copy of the parts again
// when `content` (bumped for every chunk the stream accepts) has moved since it last did, under
// the stream's lock, and draws without it.
WalkDrawFunction streamWalkDrawer(net::ModelStream& stream,
                                  const std::atomic<std::uint64_t>& content);

}  // namespace octopoint
