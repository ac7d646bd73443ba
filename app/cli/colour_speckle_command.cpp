// `lenslab colour-speckle PICTURE.png CX CY RADIUS`: issue 39's colour-speckle index of a
// disc of an 8-bit PNG (image/colour_speckle.h), the measure `lenslab bench povray` reports,
// for comparing any two renders (split and unsplit glass, 1 and 16 samples per pixel).

#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "image/colour_speckle.h"
#include "util/error.h"

namespace lenslab::cli {

namespace {

struct SpeckleArgs {
    std::string picture;
    double cx = 0, cy = 0, radius = 0;
};

int print_speckle(const SpeckleArgs& a) {
    const Image8 image = read_png(a.picture);
    const PixelDisc disc{a.cx, a.cy, a.radius};
    if (a.cx + a.radius < 0 || a.cy + a.radius < 0 || a.cx - a.radius > image.width - 1 ||
        a.cy - a.radius > image.height - 1) {
        char where[160];
        std::snprintf(where, sizeof where,
                      "the disc about (%g, %g), radius %g, lies outside the %d x %d picture ", a.cx,
                      a.cy, a.radius, image.width, image.height);
        throw Error(where + a.picture);
    }
    std::printf("%.4f\n", colour_speckle(image, disc));
    return 0;
}

}  // namespace

Action add_colour_speckle_command(CLI::App& app) {
    auto args = std::make_shared<SpeckleArgs>();
    CLI::App* cmd = app.add_subcommand(
        "colour-speckle",
        "Colour-speckle index of a disc of a PNG: each pixel's chroma (R - G, G - B) against its "
        "5 x 5 neighbourhood's mean, averaged over the disc (0: smooth colour; about 1: one "
        "random colour per pixel)");
    cmd->add_option("picture", args->picture, "8-bit PNG")->required()->check(CLI::ExistingFile);
    cmd->add_option("cx", args->cx, "Disc centre, pixels from the left")->required();
    cmd->add_option("cy", args->cy, "Disc centre, pixels from the top")->required();
    cmd->add_option("radius", args->radius, "Disc radius in pixels")
        ->required()
        ->check(CLI::PositiveNumber);
    return [args] { return print_speckle(*args); };
}

}  // namespace lenslab::cli
