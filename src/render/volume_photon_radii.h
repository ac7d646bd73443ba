#pragma once
// How wide each volume photon's disc is in sppm's beam radiance estimate (Jarosz, Zwicker and
// Jensen 2008). Where photons crowd (a laser beam, the focused cone behind a lens) a disc is a
// few pixel footprints at the photon's distance, as sharp as the image can show; where they
// are sparse (light scattered out of the beams and wandering through open fog) it grows with
// the distance to its neighbours, as a k-nearest-neighbour radius does, so that isolated
// photons spread into a glow instead of speckling the picture.

#include <functional>
#include <vector>

#include "math/vec3.h"

namespace lenslab {

struct VolumeRadiusRule {
    double radius = 0;     // the pass's volume radius (it shrinks pass by pass)
    double footprint = 0;  // the sharp disc's radius per unit of distance from the eye
    Vec3 eye;
    int neighbours = 0;  // render.volume_neighbours; 0: the sharp disc alone
};

// The sharp disc is min(radius, footprint x distance from the eye). With `neighbours` > 0,
// photons near each photon are counted in grids of cells from radius / 4 to 4 radius across;
// its density radius is 0.6 times the side of the finest cell around it that holds that many
// photons (the 4-radius cell where none does: 2.4 radius), and its disc the larger of the two.
std::vector<double> volume_photon_radii(size_t count, const std::function<Vec3(size_t)>& position,
                                        const VolumeRadiusRule& rule);

}  // namespace lenslab
