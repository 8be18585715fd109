// png_cell IN.png X Y W H OUT.png: writes the W x H pixels of IN.png at (X, Y) as OUT.png, so that
// a test can compare one cell of a contact sheet with a single view byte for byte (both written by
// the same OpenCV encoder from the same pixels).
#include <cstdio>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <string>

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: png_cell IN.png X Y W H OUT.png\n");
    return 2;
  }
  const cv::Mat image = cv::imread(argv[1], cv::IMREAD_UNCHANGED);
  const cv::Rect cell(std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4]),
                      std::atoi(argv[5]));
  if (image.empty() || cell.width <= 0 || cell.height <= 0 ||
      (cell & cv::Rect(0, 0, image.cols, image.rows)) != cell) {
    std::fprintf(stderr, "png_cell: %s: no such cell in the image\n", argv[1]);
    return 1;
  }
  if (!cv::imwrite(argv[6], image(cell).clone())) {
    std::fprintf(stderr, "png_cell: %s: cannot write\n", argv[6]);
    return 1;
  }
  return 0;
}
