#pragma once
// What a ray of the section view did, surface by surface, as a lesson reads it: the angles of
// incidence and of refraction (or reflection) against the surface's normal, the indices on
// either side, how far each surface turned the ray and how far the whole path did. The
// editor shows it for a clicked ray.

#include <string>
#include <vector>

#include "analysis/section/section_rays.h"
#include "scene/scene.h"

namespace lenslab {

struct SectionRayStep {
    int object = -1;
    std::string object_name;
    Event event = Event::Refract;
    double incidence_deg = 0;     // between the arriving ray and the normal, 0-90
    double leaving_deg = 0;       // between the leaving ray and the normal (refracted or reflected)
    double n_from = 1, n_to = 1;  // the indices the ray arrives in and leaves into
    double deviation_deg = 0;     // between the arriving and the leaving direction
};

struct SectionRayReport {
    double wavelength_nm = 0;
    std::vector<SectionRayStep> steps;  // the surfaces the path turned at, in order
    std::string end;                    // "escaped", "absorbed by screen", ...
    // Between the path's first and last directions (a prism's deviation), 0-180.
    double total_deviation_deg = 0;
};

SectionRayReport section_ray_report(const Scene& scene, const SectionRayPath& path);

// The report as lines of text: "1. prism: refracted, incidence 48.60°, refraction 30.00°,
// n 1.0000 -> 1.5168, turned 18.60°", then the end and the total.
std::string format_section_ray_report(const SectionRayReport& report);

}  // namespace lenslab
