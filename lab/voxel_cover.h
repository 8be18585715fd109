#pragma once
// The exact voxel cover (docs/tradeoff.md, "The measures"): what a level's voxels show when each
// leaf cube covers exactly the pixel centres inside its projection, no more, no less. Footprint
// splats (docs/splats.md) cover exactly those centres along an axis where a voxel spans more than
// a pixel; where it spans less, a leaf sets the one pixel holding its centre. So a level drawn at
// an odd factor K times the frame's size (voxels K times wider) and sampled at the frame's pixel
// centres (the big frame's pixel K x + (K - 1) / 2 has its centre on the small frame's pixel
// x + 1/2) is that cover to within 1/(2K) pixel: the best picture a footprint of those cubes gives
// that keeps a dense surface hole-free, whatever the size of the voxels on screen.

#include <opencv2/core.hpp>

namespace octopoint::tradeoff {

// The factor exactVoxelCover draws at for a width x height frame: 5, or 3 where 5 would pass
// the renderer's largest side (kMaxViewportSide), or 1 where 3 would too.
int voxelCoverFactor(int width, int height);

// `big` (any type) sampled at the centres of the pixels of a frame `factor` (odd, >= 1) times
// smaller: pixel (x, y) takes big's (factor x + factor / 2, factor y + factor / 2).
cv::Mat sampleAtPixelCentres(const cv::Mat& big, int factor);

}  // namespace octopoint::tradeoff
