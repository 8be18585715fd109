#pragma once
// Image quality against a reference: PSNR and SSIM (Wang et al. 2004) on 8-bit images (BGR or
// grey).

#include <opencv2/core.hpp>

namespace octopoint::tradeoff {

double psnr(const cv::Mat& reference, const cv::Mat& image);
// Mean SSIM over the channels (each with the paper's C1 and C2), Gaussian window 11x11, sigma 1.5,
// as in the paper.
double ssim(const cv::Mat& reference, const cv::Mat& image);

}  // namespace octopoint::tradeoff
