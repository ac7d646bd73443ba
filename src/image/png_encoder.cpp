#include "image/png_encoder.h"

#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace lenslab {

namespace {

// Rows per strip: enough for deflate to find the image's runs, small enough that a 900-row
// render makes a dozen strips for the threads to share.
constexpr int kStripRows = 64;
constexpr unsigned char kSubFilter = 1;

struct Strip {
    std::vector<unsigned char> deflated;
    uLong adler = 0;
    size_t filtered_size = 0;
};

// Rows [first, last) with their filter bytes, deflated raw (no zlib header), ending with a
// sync flush, or with the final block when `last_strip`.
Strip deflate_rows(int width, int first, int last, const unsigned char* rgb, bool last_strip) {
    const size_t stride = 3 * static_cast<size_t>(width);
    std::vector<unsigned char> filtered(static_cast<size_t>(last - first) * (stride + 1));
    unsigned char* out = filtered.data();
    for (int y = first; y < last; ++y) {
        const unsigned char* row = rgb + static_cast<size_t>(y) * stride;
        *out++ = kSubFilter;
        std::copy_n(row, std::min<size_t>(3, stride), out);
        for (size_t i = 3; i < stride; ++i)
            out[i] = static_cast<unsigned char>(row[i] - row[i - 3]);
        out += stride;
    }
    Strip s;
    s.filtered_size = filtered.size();
    s.adler = adler32(adler32(0, nullptr, 0), filtered.data(), static_cast<uInt>(filtered.size()));
    z_stream z{};
    if (deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_RLE) != Z_OK)
        throw std::runtime_error("zlib: cannot start deflate");
    // The bound plus a sync flush's empty stored block (5 bytes) and room to spare.
    s.deflated.resize(deflateBound(&z, static_cast<uLong>(filtered.size())) + 16);
    z.next_in = filtered.data();
    z.avail_in = static_cast<uInt>(filtered.size());
    z.next_out = s.deflated.data();
    z.avail_out = static_cast<uInt>(s.deflated.size());
    const int flush = last_strip ? Z_FINISH : Z_SYNC_FLUSH;
    const int status = deflate(&z, flush);
    const bool done = last_strip ? status == Z_STREAM_END : status == Z_OK && z.avail_in == 0;
    s.deflated.resize(z.total_out);
    deflateEnd(&z);
    if (!done) throw std::runtime_error("zlib: deflate failed (" + std::to_string(status) + ")");
    return s;
}

void put_u32(std::vector<unsigned char>& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<unsigned char>(v >> shift));
}

// A chunk: its length, type and data, and the CRC-32 of type and data.
void put_chunk(std::vector<unsigned char>& out, const char type[5],
               const std::vector<unsigned char>& data) {
    put_u32(out, static_cast<uint32_t>(data.size()));
    const size_t type_at = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    const auto* start = out.data() + type_at;
    put_u32(out, static_cast<uint32_t>(
                     crc32(crc32(0, nullptr, 0), start, static_cast<uInt>(out.size() - type_at))));
}

}  // namespace

std::vector<unsigned char> encode_png(int width, int height, const unsigned char* rgb) {
    const int strips = (height + kStripRows - 1) / kStripRows;
    std::vector<Strip> parts(static_cast<size_t>(strips));
    tbb::parallel_for(0, strips, [&](int s) {
        const int first = s * kStripRows;
        parts[static_cast<size_t>(s)] =
            deflate_rows(width, first, std::min(height, first + kStripRows), rgb, s + 1 == strips);
    });

    // The zlib stream: header (deflate, 32 KiB window, fastest), the strips, Adler-32.
    std::vector<unsigned char> zlib{0x78, 0x01};
    uLong adler = adler32(0, nullptr, 0);
    for (const Strip& s : parts) {
        zlib.insert(zlib.end(), s.deflated.begin(), s.deflated.end());
        adler = adler32_combine(adler, s.adler, static_cast<z_off_t>(s.filtered_size));
    }
    put_u32(zlib, static_cast<uint32_t>(adler));

    std::vector<unsigned char> header;
    put_u32(header, static_cast<uint32_t>(width));
    put_u32(header, static_cast<uint32_t>(height));
    // 8 bits a sample, colour type 2 (RGB), deflate, adaptive filtering, no interlace.
    header.insert(header.end(), {8, 2, 0, 0, 0});

    std::vector<unsigned char> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    png.reserve(zlib.size() + 64);
    put_chunk(png, "IHDR", header);
    put_chunk(png, "IDAT", zlib);
    put_chunk(png, "IEND", {});
    return png;
}

}  // namespace lenslab
