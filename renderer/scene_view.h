#pragma once
// One instance of a scene seen by the scene's camera (docs/city.md): the same picture as the
// instance's model drawn alone by the inverse camera, which this computes. Integer only.
//
// For an instance at A, turned by T, scaled by 2^s (octopoint/scene.h), a scene camera at E with
// yaw Y, pitch P, roll R sees the model from the eye Ry(-T) (E - A) / 2^s (Q.24 model cube edges,
// rounded once per axis) with yaw Y - T, the same pitch, roll, field of view and principal point,
// its near plane near / 2^s; depths measured in the model's units are 2^s times shorter, so its
// depth keys take s bits less of shift than the scene's (PerspectiveView::depth_shift).

#include <cstdint>

#include "octopoint/scene.h"
#include "renderer/occlusion_tiles.h"
#include "renderer/perspective.h"
#include "renderer/perspective_walk.h"

namespace octopoint {

// The scene's depth shift: kPerspectiveDepthShift plus the largest scale (at least 0), so that
// every instance's shift (the scene's minus its scale) is at least kPerspectiveDepthShift and its
// keys stay within FrameView::kMaxDepthKey. A single instance at scale 0 draws the keys its model
// draws alone.
int sceneDepthShift(int largest_scale);

// Where an instance's box lies in the scene camera's space, in the instance's model units
// (2^s scene units): its centre and its reach on every camera axis. nullopt when the instance's
// centre is more than kMaxEyeDistance of its own cube edges from the eye on some axis (the
// camera of renderer/perspective.h cannot draw it from there: beyond the draw distance).
struct InstanceBox {
  CameraPoint centre;  // Q.24 model cube edges
  std::int64_t reach = 0;
};
std::optional<InstanceBox> instanceBox(const PerspectiveView& scene_view,
                                       const InstanceTransform& transform);

// Whether the box lies wholly outside the scene camera's frustum (`tables`: the scene view's
// walk tables, whose side slopes do not depend on scale). Conservative.
bool instanceOutsideFrustum(const PerspectiveView& scene_view, const PerspectiveWalkTables& tables,
                            const InstanceTransform& transform, const InstanceBox& box);

// Whether the instance's box (instanceBox, model units; `model_depth_shift` its model view's
// shift) lies wholly behind what `tiles` hold: every pixel its projection may touch (widened by two
// pixels for the splats and the rounding) holds a word nearer than the box's nearest (words of a
// PixelPayload::kColour frame: the caller asks only for those). Then no
// point of it can change the frame: it need not be set up nor walked. False when unsure (the box
// reaches the near plane, or projects off any int32 screen).
bool instanceHidden(const PerspectiveView& scene_view, const InstanceTransform& transform,
                    const InstanceBox& box, int model_depth_shift, OcclusionTiles& tiles);

// The view of the instance's model that draws it as the scene camera sees it, with the depth
// shift `scene_depth_shift - scale`. Not kNone when that camera cannot be built (kEyeTooFar: the
// eye beyond the draw distance once turned).
PerspectiveError instanceView(const PerspectiveView& scene_view, const InstanceTransform& transform,
                              int scene_depth_shift, PerspectiveView* view);

}  // namespace octopoint
