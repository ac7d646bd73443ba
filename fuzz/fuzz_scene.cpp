// libFuzzer target: the scene reader (parse_scene) on arbitrary bytes.
// Build and run: scripts/fuzz.sh (docs/reliability.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // OBJ files a fuzzed scene names are looked up next to the example scenes (wedge.obj).
    lenslab::fuzz::read_scene_input(std::string_view(reinterpret_cast<const char*>(data), size),
                                    LENSLAB_SCENES_DIR);
    return 0;
}
