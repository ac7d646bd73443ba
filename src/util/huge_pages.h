#pragma once
// Transparent huge pages for large, freshly allocated arrays (photon storage: tens of MB).
// Each 4 KiB page touched for the first time costs a page fault, and in a virtual machine a
// fault costs microseconds: 38 MB of photons written twice made 19,000 of them, about 4% of
// a photon-map render's CPU time. Asking for 2 MiB pages also spares the kd-tree's build and
// queries most of their TLB misses.

#include <cstddef>

namespace lenslab {

// Advises the kernel to back [data, data + bytes) with huge pages where it can (Linux:
// madvise MADV_HUGEPAGE on the 2 MiB-aligned part). Only a hint: does nothing elsewhere, for
// small ranges, or when the kernel says no. Call it before the memory is first written.
void advise_huge_pages(void* data, size_t bytes);

}  // namespace lenslab
