#pragma once
// PNG encoding of 8-bit RGB pixels (ISO/IEC 15948), in parallel: the rows are cut into strips
// of a fixed height, each strip filtered and deflated on its own, and the strips' streams
// joined into the one zlib stream the format wants, as pigz joins its blocks (each but the
// last ends on a byte boundary with a sync flush; their Adler-32 checksums are combined).
// libpng deflates on one thread: 27 ms for a 900 x 900 render with its fast setting, the last
// single-threaded stretch of a render (docs/performance.md). Every row takes the Sub filter
// and the strips are run-length deflated (zlib's Z_RLE): on renders that is both faster and
// about a quarter smaller than libpng's fast setting (no filter, deflate level 3). The bytes
// depend on the pixels only, not on the number of threads.

#include <vector>

namespace lenslab {

// The PNG file of a `width` x `height` image whose pixels are `rgb`, row by row, 3 bytes a
// pixel. Throws std::runtime_error if zlib fails.
std::vector<unsigned char> encode_png(int width, int height, const unsigned char* rgb);

}  // namespace lenslab
