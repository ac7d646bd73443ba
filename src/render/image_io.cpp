#include "render/image_io.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "util/atomic_file.h"

namespace lenslab {

namespace {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext;
}

void write_png(const Image8& img, const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(img.width);
    image.height = static_cast<png_uint_32>(img.height);
    image.format = PNG_FORMAT_RGB;
    // libpng's default compression took 0.1 s for a 900x900 render, longer than rendering
    // it without photons; the fast setting writes a file about a fifth larger in a fraction.
    image.flags = PNG_IMAGE_FLAG_FAST;
    if (!png_image_write_to_file(&image, path.c_str(), 0, img.rgb.data(), 0, nullptr)) {
        throw ImageError("cannot write PNG '" + path + "': " + image.message);
    }
}

void write_exr(const Film& film, const std::string& path, double scale) {
    const int w = film.width(), h = film.height();
    std::vector<float> r(size_t(w) * h), g(r.size()), b(r.size());
    auto scaled = [scale](float v) {
        return static_cast<float>(std::min(v * scale, double(std::numeric_limits<float>::max())));
    };
    for (size_t i = 0; i < r.size(); ++i) {
        const PixelRgb& p = film.pixels()[i];
        r[i] = scaled(p.r);
        g[i] = scaled(p.g);
        b[i] = scaled(p.b);
    }
    try {
        Imf::Header header(w, h);
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        header.channels().insert("G", Imf::Channel(Imf::FLOAT));
        header.channels().insert("B", Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path.c_str(), header);
        Imf::FrameBuffer fb;
        const size_t xs = sizeof(float), ys = sizeof(float) * w;
        fb.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(r.data()), xs, ys));
        fb.insert("G", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(g.data()), xs, ys));
        fb.insert("B", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(b.data()), xs, ys));
        file.setFrameBuffer(fb);
        file.writePixels(h);
    } catch (const std::exception& e) {
        throw ImageError("cannot write EXR '" + path + "': " + e.what());
    }
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
    write_via_temporary(path, [&](const std::string& tmp) { write_png(image, tmp); });
}

void write_exr_channels(int width, int height, const std::vector<ExrChannel>& channels,
                        const std::string& path) {
    write_via_temporary(path, [&](const std::string& tmp) {
        try {
            Imf::Header header(width, height);
            for (const ExrChannel& c : channels)
                header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            Imf::OutputFile file(tmp.c_str(), header);
            Imf::FrameBuffer fb;
            const size_t xs = sizeof(float), ys = sizeof(float) * static_cast<size_t>(width);
            for (const ExrChannel& c : channels) {
                fb.insert(
                    c.name,
                    Imf::Slice(Imf::FLOAT,
                               const_cast<char*>(reinterpret_cast<const char*>(c.values.data())),
                               xs, ys));
            }
            file.setFrameBuffer(fb);
            file.writePixels(height);
        } catch (const std::exception& e) {
            throw ImageError("cannot write EXR '" + path + "': " + e.what());
        }
    });
}

double linear_to_srgb(double v) {
    if (!(v > 0.0)) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

Image8 to_srgb8(const Film& film, double exposure_stops) {
    const double scale = std::exp2(exposure_stops);
    Image8 img{film.width(), film.height(), {}};
    img.rgb.resize(size_t(img.width) * img.height * 3);
    auto encode = [&](float v) {
        return static_cast<unsigned char>(std::lround(255.0 * linear_to_srgb(v * scale)));
    };
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        const PixelRgb& p = film.pixels()[i];
        img.rgb[3 * i + 0] = encode(p.r);
        img.rgb[3 * i + 1] = encode(p.g);
        img.rgb[3 * i + 2] = encode(p.b);
    }
    return img;
}

bool is_supported_image_path(const std::string& path) {
    const std::string ext = extension_of(path);
    return ext == ".png" || ext == ".exr";
}

void write_image(const Film& film, const std::string& path, double exposure_stops) {
    const std::string ext = extension_of(path);
    if (!is_supported_image_path(path)) {
        throw ImageError("cannot write '" + path + "': unknown image type '" + ext +
                         "' (use .png or .exr)");
    }
    write_via_temporary(path, [&](const std::string& tmp) {
        if (ext == ".png") {
            write_png(to_srgb8(film, exposure_stops), tmp);
        } else {
            write_exr(film, tmp, std::exp2(exposure_stops));
        }
    });
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
