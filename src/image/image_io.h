#pragma once
// Image files: PNG (8-bit sRGB, exposure and tone map applied) and OpenEXR (linear float),
// chosen by the file name's extension.

#include <stdexcept>
#include <string>
#include <vector>

#include "image/film.h"
#include "image/tone_map.h"
#include "util/error.h"

namespace lenslab {

class ImageError : public Error {
public:
    using Error::Error;
};

// Linear value -> sRGB-encoded [0, 1] (IEC 61966-2-1 transfer function).
double linear_to_srgb(double v);
// Its inverse on [0, 1]: an sRGB-encoded value (a colour picker's) -> linear.
double srgb_to_linear(double v);

// Writes `film` to `path`: .png (sRGB through `tone`: exposure, then clipped or compressed)
// or .exr (linear, only the exposure applied). Written atomically (util/atomic_file.h): an
// interrupted or failed write never leaves a half image, nor its temporary file. Throws
// ImageError.
void write_image(const Film& film, const std::string& path, const ToneMap& tone = {});

// True if the extension is one write_image understands.
bool is_supported_image_path(const std::string& path);

// 8-bit RGB image, for reading PNGs back (golden-image tests, viewers).
struct Image8 {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;  // width * height * 3
};
Image8 read_png(const std::string& path);
// An OpenEXR file's R, G and B channels as a film (a render's linear radiances, as
// write_image stores them). Throws ImageError.
Film read_exr(const std::string& path);
Image8 to_srgb8(const Film& film, const ToneMap& tone = {});

// Writes an 8-bit image as a PNG, atomically (temporary file, then rename). Throws ImageError.
void write_png_image(const Image8& image, const std::string& path);

// One named float channel of an EXR image, `width * height` values, row 0 at the top.
struct ExrChannel {
    std::string name;
    std::vector<float> values;
};
// Writes linear float channels as an OpenEXR file, atomically. Throws ImageError.
void write_exr_channels(int width, int height, const std::vector<ExrChannel>& channels,
                        const std::string& path);

}  // namespace lenslab
