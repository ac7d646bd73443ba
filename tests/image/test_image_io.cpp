#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <vector>

#include "image/image_io.h"
#include "util/output_path.h"

namespace lenslab {
namespace {

TEST(Film, NeverHoldsInfOrNan) {
    Film f(2, 1);
    f.set(0, 0, {INFINITY, NAN, -1.0});
    EXPECT_EQ(f.at(0, 0).r, std::numeric_limits<float>::max());
    EXPECT_EQ(f.at(0, 0).g, 0.0f);
    EXPECT_EQ(f.at(0, 0).b, 0.0f);
    f.set(1, 0, {1e39, 0.5, 2.0});
    EXPECT_TRUE(std::isfinite(f.at(1, 0).r));
}

// to_srgb8 encodes through a table; each code must be the formula's exactly: checked at
// 2^20 floats spread over [0, 1] (every 1,016th bit pattern) and at the floats either side
// of every code's first value.
TEST(ImageIo, EightBitCodesAreTheFormulasExactly) {
    std::vector<float> values;
    const uint32_t one = std::bit_cast<uint32_t>(1.0f);
    for (uint32_t bits = 0; bits <= one; bits += one / (1u << 20))
        values.push_back(std::bit_cast<float>(bits));
    for (int k = 1; k <= 255; ++k) {
        // A value near code k's start, then the floats about it.
        const double v = srgb_to_linear((k - 0.5) / 255.0);
        float f = static_cast<float>(v);
        for (int step = 0; step < 8; ++step) f = std::nextafter(f, 0.0f);
        for (int step = 0; step < 16; ++step, f = std::nextafter(f, 2.0f)) values.push_back(f);
    }
    values.push_back(-0.5f);
    values.push_back(std::numeric_limits<float>::quiet_NaN());
    values.push_back(1.5f);
    Film film(int(values.size()), 1);
    for (size_t i = 0; i < values.size(); ++i)
        film.at(int(i), 0) = {values[i], values[i], values[i]};
    const Image8 image = to_srgb8(film);
    for (size_t i = 0; i < values.size(); ++i) {
        const float v = std::isnan(values[i]) ? 0.0f : values[i];
        const long expected = std::lround(255.0 * linear_to_srgb(std::clamp(v, 0.0f, 1.0f)));
        ASSERT_EQ(int(image.rgb[3 * i]), expected) << "linear " << values[i];
    }
}

TEST(ImageIo, SrgbTransferFunction) {
    // IEC 61966-2-1: linear 0.5 encodes as 0.7354, the linear segment below 0.0031308.
    EXPECT_NEAR(linear_to_srgb(0.5), 0.735357, 1e-6);
    EXPECT_NEAR(linear_to_srgb(0.002), 0.002 * 12.92, 1e-12);
    EXPECT_EQ(linear_to_srgb(2.0), 1.0);
    EXPECT_EQ(linear_to_srgb(NAN), 0.0);
}

TEST(ImageIo, PngRoundTripAndExrWrite) {
    Film f(3, 2);
    f.set(0, 0, {1, 0, 0});
    f.set(2, 1, {0.5, 0.5, 0.5});
    const auto dir = std::filesystem::temp_directory_path();
    const std::string png = (dir / "lenslab_test_io.png").string();
    write_image(f, png);
    const Image8 img = read_png(png);
    ASSERT_EQ(img.width, 3);
    ASSERT_EQ(img.height, 2);
    EXPECT_EQ(img.rgb[0], 255);
    EXPECT_EQ(img.rgb[(1 * 3 + 2) * 3], 188);  // round(255 * 0.7354)
    const std::string exr = (dir / "lenslab_test_io.exr").string();
    write_image(f, exr, ToneMap{1.0});
    EXPECT_GT(std::filesystem::file_size(exr), 0u);
    std::filesystem::remove(png);
    std::filesystem::remove(exr);
}

// A write that the file system refuses part way (as a full disk does) names its cause, not
// libpng's bare "Write Error". The refusal is made by a file-size limit (RLIMIT_FSIZE: writes
// past it fail with EFBIG, its signal ignored), lowered for this write and restored, so the
// test needs no full disk.
TEST(ImageIo, APngWriteRefusedPartWayNamesItsCause) {
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("lenslab_fsize_" + std::to_string(::getpid()) + ".png"))
                                 .string();
    Film film(64, 64);  // noise: the PNG cannot shrink below the limit
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x)
            film.set(x, y, {((x * 7919 + y * 104729) % 255) / 255.0, (x ^ y) / 64.0, 0.5});
    }
    rlimit saved{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
    const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = saved;
    small.rlim_cur = 512;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string message = "no error";
    try {
        write_image(film, file);
    } catch (const ImageError& e) {
        message = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, old_handler);
    EXPECT_EQ(message, "cannot write '" + file + "': " + error_reason(EFBIG));
    // Nothing is left under the name.
    EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(ImageIo, RefusesUnknownExtensions) {
    EXPECT_FALSE(is_supported_image_path("out.bmp"));
    EXPECT_TRUE(is_supported_image_path("OUT.PNG"));
    EXPECT_THROW(write_image(Film(1, 1), "/tmp/x.bmp"), ImageError);
}

TEST(ImageIo, ExrReadsBackWhatWasWritten) {
    Film f(3, 2);
    f.set(0, 0, {1.5f, 0.25f, 1e-7f});
    f.set(2, 1, {1e6f, 0.5f, 3.0f});
    const std::string exr =
        (std::filesystem::temp_directory_path() / "lenslab_test_read.exr").string();
    write_image(f, exr);
    const Film back = read_exr(exr);
    ASSERT_EQ(back.width(), 3);
    ASSERT_EQ(back.height(), 2);
    for (size_t i = 0; i < f.pixels().size(); ++i) {
        EXPECT_EQ(back.pixels()[i].r, f.pixels()[i].r);
        EXPECT_EQ(back.pixels()[i].g, f.pixels()[i].g);
        EXPECT_EQ(back.pixels()[i].b, f.pixels()[i].b);
    }
    std::filesystem::remove(exr);
    EXPECT_THROW(read_exr(exr), ImageError);  // gone
}

}  // namespace
}  // namespace lenslab
