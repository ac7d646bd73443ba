// libFuzzer target: lenslab's OBJ reader (src/scene/obj_reader.h) on arbitrary bytes.
// Build and run: scripts/fuzz.sh (docs/reliability.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    lenslab::fuzz::read_obj_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
