#include "image/image_io.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <png.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>

#include "image/png_encoder.h"
#include "util/atomic_file.h"

namespace lenslab {

namespace {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext;
}

// `img` as a PNG file `file`; `path` is the name messages give. Encoded in memory
// (image/png_encoder.h, in parallel) and written by write_whole_file, whose every write is
// checked: a full disk is reported with its cause.
void write_png(const Image8& img, const std::string& file, const std::string& path) {
    std::vector<unsigned char> png;
    try {
        png = encode_png(img.width, img.height, img.rgb.data());
    } catch (const std::runtime_error& e) {
        throw ImageError("cannot write PNG '" + path + "': " + e.what());
    }
    try {
        write_whole_file(file, {reinterpret_cast<const char*>(png.data()), png.size()}, path);
    } catch (const FileWriteError& e) {
        throw ImageError(e.what());
    }
}

// The channels as an OpenEXR file `file`; `path` is the name messages give. The stream is
// ours, not OpenEXR's, so that its close is checked: the last buffered bytes (and on a small
// image all of them) reach the disk only then, and a full disk must not pass as success.
void write_exr_file(const std::string& file, const std::string& path, int width, int height,
                    const std::vector<ExrChannel>& channels) {
    std::ofstream stream(file, std::ios::binary | std::ios::trunc);
    if (!stream) throw ImageError(output_error(path, error_reason(errno)).what());
    try {
        Imf::StdOFStream out(stream, file.c_str());
        Imf::Header header(width, height);
        for (const ExrChannel& c : channels)
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
        Imf::OutputFile exr(out, header);
        Imf::FrameBuffer fb;
        const size_t xs = sizeof(float), ys = sizeof(float) * static_cast<size_t>(width);
        for (const ExrChannel& c : channels) {
            fb.insert(c.name,
                      Imf::Slice(Imf::FLOAT,
                                 const_cast<char*>(reinterpret_cast<const char*>(c.values.data())),
                                 xs, ys));
        }
        exr.setFrameBuffer(fb);
        exr.writePixels(height);
    } catch (const std::exception& e) {
        throw ImageError("cannot write EXR '" + path + "': " + e.what());
    }
    errno = 0;
    stream.close();
    if (!stream) {
        throw ImageError(
            output_error(path, errno ? error_reason(errno) : "the write failed").what());
    }
}

void write_exr(const Film& film, const std::string& file, const std::string& path, double scale) {
    const size_t n = film.pixels().size();
    std::vector<ExrChannel> channels{
        {"R", std::vector<float>(n)}, {"G", std::vector<float>(n)}, {"B", std::vector<float>(n)}};
    auto scaled = [scale](float v) {
        return static_cast<float>(std::min(v * scale, double(std::numeric_limits<float>::max())));
    };
    for (size_t i = 0; i < n; ++i) {
        const PixelRgb& p = film.pixels()[i];
        channels[0].values[i] = scaled(p.r);
        channels[1].values[i] = scaled(p.g);
        channels[2].values[i] = scaled(p.b);
    }
    write_exr_file(file, path, film.width(), film.height(), channels);
}

// write_atomically (util/atomic_file.h), with a failed rename reported as an ImageError
// like every other failure here.
template <class Write>
void write_via_temporary(const std::string& path, Write write) {
    try {
        write_atomically(path, write);
    } catch (const FileWriteError& e) {
        throw ImageError(e.what());
    }
}

}  // namespace

void write_png_image(const Image8& image, const std::string& path) {
    write_via_temporary(path, [&](const std::string& tmp) { write_png(image, tmp, path); });
}

void write_exr_channels(int width, int height, const std::vector<ExrChannel>& channels,
                        const std::string& path) {
    write_via_temporary(
        path, [&](const std::string& tmp) { write_exr_file(tmp, path, width, height, channels); });
}

double linear_to_srgb(double v) {
    if (!(v > 0.0)) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double srgb_to_linear(double v) {
    if (!(v > 0.0)) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

namespace {

// The 8-bit sRGB code of a linear value, std::lround(255 * linear_to_srgb(v)), without a pow
// per channel (2.4 million of them took 0.07 s for a 900 x 900 picture, on one thread): the
// smallest float of each code, found once by bisection over the floats' bit patterns (ordered
// as integers for v >= 0) against that very formula, and a table of the code at the start of
// each of kBuckets equal steps of [0, 1], from which a value walks up at most a code or two.
class Srgb8Encoder {
public:
    Srgb8Encoder() {
        const auto code_of = [](float v) { return std::lround(255.0 * linear_to_srgb(v)); };
        for (int k = 1; k <= 255; ++k) {
            uint32_t lo = 0, hi = std::bit_cast<uint32_t>(1.0f);  // code(lo) < k <= code(hi)
            while (hi - lo > 1) {
                const uint32_t mid = lo + (hi - lo) / 2;
                (code_of(std::bit_cast<float>(mid)) >= k ? hi : lo) = mid;
            }
            m_first[k] = std::bit_cast<float>(hi);
        }
        for (int b = 0; b < kBuckets; ++b) m_bucket[b] = walk(0, float(b) / kBuckets);
    }

    unsigned char operator()(float v) const {
        if (!(v > 0.0f)) return 0;
        if (v >= 1.0f) return 255;
        return walk(m_bucket[static_cast<int>(v * kBuckets)], v);
    }

private:
    static constexpr int kBuckets = 4096;

    unsigned char walk(int code, float v) const {
        while (code < 255 && v >= m_first[code + 1]) ++code;
        return static_cast<unsigned char>(code);
    }

    float m_first[256] = {};  // m_first[k]: the smallest value of code k (k >= 1)
    unsigned char m_bucket[kBuckets] = {};
};

}  // namespace

Image8 to_srgb8(const Film& film, const ToneMap& tone) {
    static const Srgb8Encoder encode;
    Image8 img{film.width(), film.height(), {}};
    img.rgb.resize(size_t(img.width) * img.height * 3);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, film.pixels().size(), 4096),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i != r.end(); ++i) {
                              const PixelRgb p = tone.apply(film.pixels()[i]);
                              img.rgb[3 * i + 0] = encode(p.r);
                              img.rgb[3 * i + 1] = encode(p.g);
                              img.rgb[3 * i + 2] = encode(p.b);
                          }
                      });
    return img;
}

bool is_supported_image_path(const std::string& path) {
    const std::string ext = extension_of(path);
    return ext == ".png" || ext == ".exr";
}

void write_image(const Film& film, const std::string& path, const ToneMap& tone) {
    const std::string ext = extension_of(path);
    if (!is_supported_image_path(path)) {
        throw ImageError("cannot write '" + path + "': unknown image type '" + ext +
                         "' (use .png or .exr)");
    }
    write_via_temporary(path, [&](const std::string& tmp) {
        if (ext == ".png") {
            write_png(to_srgb8(film, tone), tmp, path);
        } else {
            write_exr(film, tmp, path, std::exp2(tone.exposure_stops));
        }
    });
}

Film read_exr(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        if (window.min.x != 0 || window.min.y != 0)
            throw ImageError("cannot read EXR '" + path +
                             "': its data window does not start at 0, 0");
        const int width = window.max.x + 1, height = window.max.y + 1;
        const size_t n = size_t(width) * size_t(height);
        std::vector<float> channel[3] = {std::vector<float>(n), std::vector<float>(n),
                                         std::vector<float>(n)};
        Imf::FrameBuffer fb;
        const char* names[3] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) {
            if (!file.header().channels().findChannel(names[c]))
                throw ImageError("cannot read EXR '" + path + "': it has no " + names[c] +
                                 " channel");
            fb.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(channel[c].data()),
                                           sizeof(float), sizeof(float) * size_t(width)));
        }
        file.setFrameBuffer(fb);
        file.readPixels(0, height - 1);
        Film film(width, height);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const size_t i = size_t(y) * width + x;
                film.set(x, y, {channel[0][i], channel[1][i], channel[2][i]});
            }
        }
        return film;
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& e) {
        throw ImageError("cannot read EXR '" + path + "': " + e.what());
    }
}

Image8 read_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str())) {
        throw ImageError("cannot read PNG '" + path + "': " + image.message);
    }
    image.format = PNG_FORMAT_RGB;
    Image8 img{static_cast<int>(image.width), static_cast<int>(image.height), {}};
    img.rgb.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, img.rgb.data(), 0, nullptr)) {
        throw ImageError("cannot read PNG '" + path + "': " + image.message);
    }
    return img;
}

}  // namespace lenslab
