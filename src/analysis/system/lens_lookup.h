#pragma once
// The lens a user names for the optical bench (`lenslab analyze --lens`, lenslab.analyze's
// `lens=`): its `name`, its lens group's name, or its path "objects[i]".

#include <optional>
#include <string>

#include "scene/scene.h"

namespace lenslab {

struct LensLookup {
    std::optional<int> index;  // into scene.objects; none when no lens answers to the name
    std::string known;         // the scene's lenses, "name [group], ...", for the message
};

LensLookup find_lens(const Scene& scene, const std::string& name);

// "no lens named 'NAME' in WHERE (lenses: ...)" or "... (it has no lens)".
std::string no_lens_message(const std::string& name, const std::string& where,
                            const LensLookup& lookup);

}  // namespace lenslab
