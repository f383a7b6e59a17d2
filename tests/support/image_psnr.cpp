// image_psnr A.png B.png: prints the PSNR of B against A in dB ("inf" for
// identical pictures), with the same measure as every picture test
// (assets::psnr), for the browser tests (tests/web/browser_test.py). Exit 2
// when a file cannot be read or the sizes differ.
#include <cstdio>
#include <exception>

#include "assets/image.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: image_psnr A.png B.png\n");
    return 2;
  }
  try {
    const atrium::assets::Image a = atrium::assets::read_png(argv[1]);
    const atrium::assets::Image b = atrium::assets::read_png(argv[2]);
    if (a.width != b.width || a.height != b.height) {
      std::fprintf(stderr, "image_psnr: %s is %dx%d, %s is %dx%d\n", argv[1], a.width, a.height, argv[2], b.width, b.height);
      return 2;
    }
    std::printf("%.3f\n", atrium::assets::psnr(a, b));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "image_psnr: %s\n", e.what());
    return 2;
  }
  return 0;
}
