#pragma once
// The sppm integrator's per-pixel and per-pass state (sppm.h), shared by the files its pass is
// split into: camera paths (sppm_camera_paths.cpp), the surface gather
// (sppm_surface_gather.cpp), the volume gather (sppm_volume_gather.cpp) and the exchange
// between the ranks of a job (sppm_cluster.cpp). Private to the integrator.

#include <cstdint>

#include "math/ray.h"
#include "optics/rgb.h"
#include "optics/spectrum.h"
#include "render/camera.h"
#include "render/integrators/sppm.h"
#include "scene/medium.h"

namespace lenslab::sppm {

// The pass wavelengths' rotation uses the stream just below this one, apart from the camera
// paths' (pixel index) and the photons' (2^62 + photon index). (Streams from here up once
// rotated the visible points' wavelengths, before their colour became exact.)
constexpr uint64_t kRotationStream = uint64_t{1} << 61;
// The volume gather's transmittance walks through heterogeneous media: from here up, one
// stream per pixel segment, above the photons'.
constexpr uint64_t kGatherStreams = uint64_t{3} << 62;
// Segments through media a camera path keeps for the volume gather (a ray through a fog box,
// a lens in it, and out again is three).
constexpr int kMaxSegments = 4;

}  // namespace lenslab::sppm

namespace lenslab {

struct SppmIntegrator::Pixel {
    double radius = 0;  // 0 until the pixel's first visible point
    double n = 0;       // photons kept so far (N)
    Rgb tau;            // their flux times the reflectance, scaled as the radius shrank
    Rgb direct;         // radiance found by tracing, summed over passes
};

struct SppmIntegrator::VisiblePoint {
    Vec3 p, n;        // n: the normal on the side the camera sees
    double beta = 0;  // path throughput to the point
    const Spectrum* albedo = nullptr;
    BandWeights albedo_bands{};  // the same albedo, per band
    double path_length = 0;      // camera to point, through mirrors and glass
    bool valid = false;          // the path reached a diffuse surface
    bool dispersed = false;      // it went through dispersive glass: pass wavelength only
    bool in_medium = false;      // it crossed a medium (its segments gather volume photons)
    Rgb direct;
};

struct SppmIntegrator::MediumSegment {
    Ray ray;
    double t_max = 0;  // where it meets the next surface (INFINITY: none)
    double beta = 0;   // the camera path's throughput at the ray's origin; 0: no segment
    const Medium* medium = nullptr;
    bool dispersed = false;  // the path follows the pass wavelength alone
};

struct SppmIntegrator::PassState {
    int index = 0;
    uint64_t seed = 0;
    double lambda_nm = 550, lambda_pdf = 1;
    Camera camera;
};

}  // namespace lenslab
