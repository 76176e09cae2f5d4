// Entry point of the `ispm` executable: the subcommands live in app/cli/.
#include "cli/cli.h"

#include <cstdlib> // defines __GLIBC__ with the GNU C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // Memory that is freed every frame stays with the process. A software rasterizer (llvmpipe)
    // allocates and frees megabytes in every frame's draws; by default glibc hands the free top of
    // the heap back to the kernel past 128 KiB, and the next frame faults the same pages in again,
    // zero-filled: on the Cornell box at 256x256, 2,000-4,000 page faults a frame, with the splat
    // pass at twice its time in about half the processes (whether the freed memory lay at the
    // heap's top). Up to 256 MiB of free heap is kept instead.
    constexpr int kKeptFreeHeapBytes = 256 << 20;
    mallopt(M_TRIM_THRESHOLD, kKeptFreeHeapBytes);
#endif
    return ispm::runCli(argc, argv);
}
