// The parallel PNG encoder (image/png_encoder.h) writes files libpng reads back pixel for
// pixel (libpng checks every chunk's CRC and inflate the stream's Adler-32), the same bytes
// at any thread count.

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "image/png_encoder.h"
#include "math/rng.h"

namespace lenslab {
namespace {

// Pixels that are partly noise (deflate's worst case) and partly smooth (its best).
std::vector<unsigned char> test_pixels(int width, int height) {
    std::vector<unsigned char> rgb(3 * static_cast<size_t>(width) * static_cast<size_t>(height));
    Rng rng(7, 1);
    for (size_t i = 0; i < rgb.size(); ++i) {
        const size_t pixel = i / 3;
        rgb[i] = pixel % 5 == 0 ? static_cast<unsigned char>(rng.uniform() * 256)
                                : static_cast<unsigned char>((pixel / 7 + i % 3 * 40) % 256);
    }
    return rgb;
}

Image8 read_back(const std::vector<unsigned char>& png) {
    const std::string file =
        (std::filesystem::temp_directory_path() / "lenslab_test_png_encoder.png").string();
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    Image8 img = read_png(file);
    std::filesystem::remove(file);
    return img;
}

TEST(PngEncoder, LibpngReadsBackEveryPixel) {
    // One pixel; one row; a strip and one row more (the strips are 64 rows); many strips.
    for (auto [w, h] : {std::pair{1, 1}, {7, 1}, {5, 65}, {300, 200}, {901, 129}}) {
        const std::vector<unsigned char> rgb = test_pixels(w, h);
        const std::vector<unsigned char> png = encode_png(w, h, rgb.data());
        const unsigned char signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
        ASSERT_TRUE(std::equal(signature, signature + 8, png.begin()));
        const Image8 img = read_back(png);
        ASSERT_EQ(img.width, w);
        ASSERT_EQ(img.height, h);
        EXPECT_EQ(img.rgb, rgb) << w << " x " << h;
    }
}

TEST(PngEncoder, TheSameBytesAtOneAndTwoThreads) {
    const std::vector<unsigned char> rgb = test_pixels(640, 480);
    std::vector<unsigned char> one, two;
    tbb::task_arena(1).execute([&] { one = encode_png(640, 480, rgb.data()); });
    tbb::task_arena(2).execute([&] { two = encode_png(640, 480, rgb.data()); });
    EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace lenslab
