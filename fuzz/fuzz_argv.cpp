// libFuzzer target: the command line of `lenslab` (app/cli/cli_parse.h), parsed and validated
// but not run. The bytes are the arguments, split at NUL and newline bytes.
// Build and run: scripts/fuzz.sh (docs/reliability.md).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    lenslab::fuzz::parse_argv_input(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
