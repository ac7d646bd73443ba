#include "analysis/section/section_ray_report.h"

#include <cstdio>

#include "util/format_number.h"

namespace lenslab {

namespace {

// What the light did, in the words of a lesson.
const char* event_words(Event e) {
    switch (e) {
        case Event::Refract:
            return "refracted";
        case Event::Reflect:
            return "reflected";
        case Event::Tir:
            return "totally reflected";
        case Event::Absorb:
            return "absorbed";
        case Event::Escape:
            return "escaped";
    }
    return "";
}

}  // namespace

SectionRayReport section_ray_report(const Scene& scene, const SectionRayPath& path) {
    SectionRayReport report;
    report.wavelength_nm = path.wavelength_nm;
    const std::vector<Vec3>& p = path.points;
    for (size_t k = 0; k < path.hits.size() && k + 1 < p.size(); ++k) {
        const SectionHit& hit = path.hits[k];
        if (k + 2 >= p.size()) {  // the path's last point: where it ended
            report.end = hit.object < 0 ? std::string("escaped")
                                        : std::string(event_words(hit.event)) + " at " +
                                              scene.objects[size_t(hit.object)].name;
            break;
        }
        const Vec3 in = normalize(p[k + 1] - p[k]), out = normalize(p[k + 2] - p[k + 1]);
        SectionRayStep step;
        step.object = hit.object;
        step.object_name = scene.objects[size_t(hit.object)].name;
        step.event = hit.event;
        step.incidence_deg = angle_to_normal_deg(in, hit.normal);
        step.leaving_deg = angle_to_normal_deg(out, hit.normal);
        const bool entering = dot(in, hit.normal) < 0;
        step.n_from = entering ? hit.n_outside : hit.n_inside;
        step.n_to =
            hit.event == Event::Refract ? (entering ? hit.n_inside : hit.n_outside) : step.n_from;
        step.deviation_deg = angle_between_deg(in, out);
        report.steps.push_back(step);
    }
    if (p.size() >= 2) {
        report.total_deviation_deg =
            angle_between_deg(p[1] - p[0], p[p.size() - 1] - p[p.size() - 2]);
    }
    return report;
}

std::string format_section_ray_report(const SectionRayReport& r) {
    std::string text = printf_text("Ray at %.1f nm\n", r.wavelength_nm);
    int k = 0;
    for (const SectionRayStep& s : r.steps) {
        const bool refracted = s.event == Event::Refract;
        text += printf_text("%d. %s: %s, incidence %.2f°, %s %.2f°, n %.4f -> %.4f, turned %.2f°\n",
                            ++k, s.object_name.c_str(), event_words(s.event), s.incidence_deg,
                            refracted ? "refraction" : "reflection", s.leaving_deg, s.n_from,
                            s.n_to, s.deviation_deg);
    }
    if (!r.end.empty()) text += "Then " + r.end + ".\n";
    text += printf_text("Deviation from first to last direction: %.2f°", r.total_deviation_deg);
    return text;
}

}  // namespace lenslab
