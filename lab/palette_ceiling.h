#pragma once
// The palette ceiling (docs/tradeoff.md, "The measures"): a plain octopoint frame holds only its
// model's palette colours and the background (octopoint/framebuffer.h resolveToRgb; hole filling
// copies neighbours' pixels), so no frame drawn from that model can be nearer the reference than
// the reference with each pixel replaced by the nearest of those colours. Nearest in the squared
// error summed over the channels, which is what PSNR averages: that replacement minimizes every
// pixel's term, so its PSNR is an exact upper bound on the PSNR of any such frame.

#include <opencv2/core.hpp>
#include <vector>

#include "octopoint/model.h"

namespace octopoint::tradeoff {

// The colours a plain frame of `model` can hold, in BGR: its palette entries, then `background`.
std::vector<cv::Vec3b> frameColours(const ModelView& model, Rgb background);

// `image` (8-bit BGR) with each pixel replaced by the nearest of `colours` (the first on ties).
cv::Mat nearestColours(const cv::Mat& image, const std::vector<cv::Vec3b>& colours);

// PSNR (lab/image_quality.h) of nearestColours(reference, colours) against `reference`.
double paletteCeilingPsnr(const cv::Mat& reference, const std::vector<cv::Vec3b>& colours);

}  // namespace octopoint::tradeoff
