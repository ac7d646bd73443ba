#pragma once
// The integrators' names as the scene file and --integrator spell them, for code that sets
// one as data (a benchmark's path-traced reference, the editor's view). The registry
// (integrator_registry.h) binds each to its integrator; the scene reader's list of accepted
// names, kIntegratorNames (src/scene cannot include src/render), is checked against it.

#include <string_view>

namespace lenslab::integrators {

inline constexpr std::string_view kWhitted = "whitted";
inline constexpr std::string_view kPhotonMap = "photon_map";
inline constexpr std::string_view kSppm = "sppm";
inline constexpr std::string_view kPath = "path";

// The one the editor's view renders with unless told to use the scene's: progressive, and
// it converges to the full light transport, caustics included.
inline constexpr std::string_view kView = kSppm;

}  // namespace lenslab::integrators
