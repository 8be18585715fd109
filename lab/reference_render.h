#pragma once
// The dense reference render the speed/accuracy trade is measured against (docs/tradeoff.md): the
// scan's surface (lab/reference_surface.h) drawn in double precision, with the scan's own colours
// (not the palette's), through the same orthographic camera as octopoint, z-buffered.
//
// Coverage is decided at pixel centres: pixel (col, row) spans [col, col + 1) x [row, row + 1) of
// the screen (octopoint's own convention: a point at x lands on pixel floor(x)), and
//   - a triangle covers it when its centre (col + 0.5, row + 0.5) lies inside the projected
//     triangle or on its edge; depth and colour are interpolated linearly across the triangle
//     (barycentric weights of the centre: Gouraud colour, rounded to nearest);
//   - a splat covers the pixels whose centre lies within its projected radius of its point;
//     depth and colour are the point's (a flat disc facing the viewer).
// Both are the same rule: the scan's surface is a set of triangles or discs, and a pixel shows it
// when its centre does. A triangle or disc smaller than a pixel may thus cover none (as a stray
// point does at low zoom).
// The nearest (smallest z) wins each pixel. The covered pixels are the object's silhouette.

#include <opencv2/core.hpp>

#include "codegen/cube_fit.h"
#include "lab/reference_surface.h"
#include "octopoint/camera.h"
#include "octopoint/model.h"

namespace octopoint::tradeoff {

// The reference's projection, in double precision: the camera's rotation (referenceRotation) about
// the fitted cube's centre, scaled so that the cube's edge spans zoom x min(width, height) pixels,
// centred on the frame plus the pan. x and y are in pixels, z in scan units (smaller is nearer).
class ScreenProjection {
 public:
  ScreenProjection(const prepare::CubeFit& fit, const Camera& camera);
  std::array<double, 3> operator()(const std::array<float, 3>& position) const;
  double pixelsPerUnit() const { return pixels_per_unit_; }

 private:
  std::array<std::array<double, 3>, 3> rotation_;
  std::array<double, 3> centre_;
  double pixels_per_unit_;
  double screen_x_, screen_y_;
};

// `fit` is the cube the model was fitted into (so both renders share the same framing). Returns an
// 8-bit BGR image and sets `covered` (CV_8U, 255 where the surface is) to the object's silhouette.
cv::Mat renderReference(const ReferenceSurface& surface, const prepare::CubeFit& fit,
                        const Camera& camera, Rgb background, cv::Mat* covered);

}  // namespace octopoint::tradeoff
