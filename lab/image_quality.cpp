#include "lab/image_quality.h"

#include <opencv2/imgproc.hpp>

namespace octopoint::tradeoff {

double psnr(const cv::Mat& reference, const cv::Mat& image) { return cv::PSNR(reference, image); }

double ssim(const cv::Mat& reference, const cv::Mat& image) {
  constexpr double kC1 = (0.01 * 255) * (0.01 * 255);
  constexpr double kC2 = (0.03 * 255) * (0.03 * 255);
  cv::Mat a, b;
  reference.convertTo(a, CV_32F);
  image.convertTo(b, CV_32F);
  auto blur = [](const cv::Mat& m) {
    cv::Mat out;
    cv::GaussianBlur(m, out, cv::Size(11, 11), 1.5);
    return out;
  };
  const cv::Mat mu_a = blur(a), mu_b = blur(b);
  const cv::Mat mu_a2 = mu_a.mul(mu_a), mu_b2 = mu_b.mul(mu_b), mu_ab = mu_a.mul(mu_b);
  const cv::Mat sigma_a2 = blur(a.mul(a)) - mu_a2;
  const cv::Mat sigma_b2 = blur(b.mul(b)) - mu_b2;
  const cv::Mat sigma_ab = blur(a.mul(b)) - mu_ab;
  // The constants go to every channel: a plain double added to a cv::Mat is cv::Scalar(c, 0, 0, 0),
  // which would stabilize the first channel only (and leave 0 / 0 in the others where flat).
  const cv::Scalar c1 = cv::Scalar::all(kC1), c2 = cv::Scalar::all(kC2);
  cv::Mat numerator = (2 * mu_ab + c1).mul(2 * sigma_ab + c2);
  cv::Mat denominator = (mu_a2 + mu_b2 + c1).mul(sigma_a2 + sigma_b2 + c2);
  cv::Mat map;
  cv::divide(numerator, denominator, map);
  const cv::Scalar mean = cv::mean(map);
  double sum = 0;
  for (int channel = 0; channel < map.channels(); ++channel) sum += mean[channel];
  return sum / map.channels();
}

}  // namespace octopoint::tradeoff
