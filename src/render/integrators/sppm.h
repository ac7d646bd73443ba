#pragma once
// Stochastic progressive photon mapping (Hachisuka & Jensen 2009, "Stochastic Progressive
// Photon Mapping"). Each pass:
//   1. traces one camera path per pixel through mirrors and glass to a diffuse surface, its
//      visible point; the light found on the way (emission, direct light through shadow
//      rays, ambient, background) is added at once;
//   2. traces render.pass_photons photons per light (sppm_photons.h): caustics and indirect
//      light, stored where they meet diffuse surfaces;
//   3. gathers, for every pixel, the photons within its radius r on the same side of the
//      same surface (a hash grid), and updates the pixel's statistics:
//        N' = N + alpha M,  r'^2 = r^2 N' / (N + M),  tau' = (tau + Phi) r'^2 / r^2
//      (M photons found, Phi their flux weighted by the visible point's reflectance).
// After k passes of n photons the pixel's radiance is direct / k + tau / (k pi r^2): the
// radius shrinks, the photon count grows without bound, and the estimate converges to the
// right answer (no trade-off between the radius and the photon count, unlike photon_map).
//
// The initial radius (render.initial_radius, 0 = auto) is per pixel: 2 pixel footprints at
// the distance of its first visible point, at most 0.5% of the scene's diagonal.
//
// Spectra: a visible point not behind dispersive glass has an exact colour, as has each
// photon's flux there (its light's band colours times band-constant albedos,
// render/path_colour.h); paths through dispersive glass take the pass's wavelength
// (pass_wavelength.h) and count through the density it was drawn with. Output is the same
// for any thread count: per-pixel and per-photon random streams, and each pixel sums its
// photons in photon order.
//
// Participating media (fog, smoke): a camera path crossing a medium is dimmed by its
// transmittance, gathers the single scattering of points, spots and beams exactly
// (medium_transport.h), and after the photon pass gathers the volume photons whose discs its
// segment crosses: the beam radiance estimate (Jarosz, Zwicker and Jensen 2008),
//   L = sum_p T(t_p) p(cos theta_p) Phi_p / (pi r^2),
// t_p where photon p projects onto the segment, theta_p between its travel and the way to the
// camera. That light refracted by a lens into fog shows where it goes: the converging cone,
// the focus. A photon's radius r is 3 pixel footprints at its distance from the camera, at
// most the volume radius, which starts at render.initial_radius (auto: 0.5% of the scene's
// diagonal); both shrink pass by pass as r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) (Knaus and
// Zwicker 2011), each pass's estimate averaged, so the estimate converges as the surface one
// does.
//
// In a job of several ranks (src/cluster/) the pass is split twice: camera paths and the
// gather by image rows (row y to rank y mod N), photons by chunk (chunk c to rank c mod N).
// Per pass every rank sends every other its photon hits (32 bytes each, plus 4 per diffuse
// bounce) and per pixel of its rows the radius and two flags (9 bytes); rank 0 receives the
// pixels' statistics once at the end (64 bytes a pixel). Every rank then sees the photons in
// the order one process traces them and gathers its pixels exactly as it would: the image
// is the same, byte for byte, at any number of ranks.

#include <vector>

#include "cluster/communicator.h"
#include "render/integrator.h"
#include "render/pass_wavelength.h"

namespace lenslab {

struct SppmStats {
    int passes = 0;
    int64_t photons_emitted = 0;  // over all passes
    int64_t photons_aimed = 0;    // of which aimed at the photon targets
    size_t photon_hits = 0;       // stored in the last pass
    double camera_seconds = 0, photon_seconds = 0, gather_seconds = 0;  // summed over passes
    double mean_radius = 0;     // over pixels with a visible point, after the last pass
    size_t volume_photons = 0;  // stored in media in the last pass
    double volume_radius = 0;   // of the last pass
};

class SppmIntegrator final : public ProgressiveIntegrator {
public:
    explicit SppmIntegrator(const Scene& scene);
    ~SppmIntegrator() override;

    bool add_pass(RenderControl& control) override;
    int passes() const override { return m_stats.passes; }
    void develop(Film& film) const override;
    // SppmStats as values; summary "sppm: N passes, ...", its rates over `seconds`.
    RenderStats stats(double seconds) const override;

private:
    struct Pixel;
    struct VisiblePoint;
    struct PassState;
    struct MediumSegment;
    class PhotonColours;

    // A pass's steps, in the order add_pass takes them (sppm.cpp), each in a file of its own.
    struct PhotonPassSettings photon_pass_settings() const;
    PassState next_pass() const;
    int64_t pass_photons() const;
    // Camera paths (sppm_camera_paths.cpp): every pixel's visible point, and a new pixel's
    // radius; false when cancelled. `segments`: where the path's segments through media go
    // (sppm::kMaxSegments; nullptr: none).
    bool trace_camera_paths(const PassState& pass, RenderControl& control);
    void trace_camera_path(int x, int y, const PassState& pass, VisiblePoint& vp,
                           MediumSegment* segments) const;
    double auto_radius(double path_length) const;
    // The share of the pass's photons that take the pass wavelength.
    double dispersed_photon_share() const;
    // The gathers (sppm_surface_gather.cpp, sppm_volume_gather.cpp); the surface one returns
    // the photon hits it looked through.
    size_t gather_surface(const struct PhotonPass& photons, const PhotonColours& colours);
    void gather_volume(const PassState& pass, const struct PhotonPass& photons,
                       const PhotonColours& colours);
    // The exchange between ranks (sppm_cluster.cpp): the visible points' radii and flags of
    // the rows dealt to others, the pixels of every row at rank 0, the mean radius.
    void share_visible_points(Communicator& comm);
    std::vector<std::vector<Pixel>> pixel_rows_at_root() const;
    double mean_radius() const;

    const Scene& m_scene;
    int m_width, m_height;
    double m_pixel_angle;  // angle one pixel subtends, radians (small-angle)
    double m_radius_cap;   // largest automatic initial radius
    PassWavelength m_pass_wavelength;
    SpectrumPtr m_ambient, m_background;  // null when black
    std::vector<Pixel> m_pixels;
    std::vector<VisiblePoint> m_points;  // this pass's, kept to reuse the memory
    // Media: each pixel's segments through them this pass (kMaxSegments a pixel), and the
    // volume radius of the next pass. Empty and 0 in a scene without media.
    std::vector<MediumSegment> m_segments;
    double m_volume_radius = 0, m_volume_radius_start = 0;
    Aabb m_volume_box;  // where volume photons are kept (empty without media)
    SppmStats m_stats;
    Communicator* m_cluster = &this_process_alone();  // of the last pass, for develop()
};

}  // namespace lenslab
