#include "app/cli.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // Keep freed heap memory instead of handing it back to the kernel. A software
  // rasteriser (llvmpipe) frees and re-allocates its binned scene every frame;
  // with glibc's default 128 KiB trim threshold each frame faulted those pages in
  // again, which on a virtual machine cost up to 120 ms of a 35 ms geometry pass
  // at random (docs/benchmarks.md). The frames this keeps are bounded by what
  // one frame allocates.
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  return atrium::run_cli(argc, argv);
}
