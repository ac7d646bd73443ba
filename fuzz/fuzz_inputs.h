#pragma once
// One fuzz input fed to a reader of user text, shared by the libFuzzer targets (fuzz/) and
// the replay test that keeps every corpus file and every past crash passing under gcc
// (tests/fuzz/test_fuzz_replay.cpp).
//
// Each function returns normally when the input was accepted or refused the documented way
// (SceneError, FormulaError, ObjError). Anything else escapes: another exception, a crash,
// undefined behaviour, a hang or a huge allocation is a finding.

#include <string>
#include <string_view>

namespace lenslab::fuzz {

// The scene reader: parse_scene() on the bytes as JSON text. Relative OBJ paths resolve in
// `base_dir`. A scene that reads is also given one camera ray, so its shapes get hit.
void read_scene_input(std::string_view data, const std::string& base_dir);

// The formula parser: the first byte picks the variables (sag r; sag x, y, r; implicit
// x, y, z), the rest up to a NUL byte is the formula. One that parses is evaluated at a few
// fixed points, at the points spelled by the bytes after the NUL (8 bytes a coordinate, any
// double: NaN, infinities, subnormals), and at points drawn from a stream seeded by the
// input; why_not_finite() is asked too. Results may be NaN; crashes and UB are findings.
void parse_formula_input(std::string_view data);

// The OBJ reader: read_obj() on the bytes as an OBJ file. A file that reads is checked for
// what the mesh builder relies on (every corner a defined vertex, every face 3 or more
// corners, within the limits); a broken promise throws std::logic_error, a finding.
void read_obj_input(std::string_view data);

// The command line: the bytes split at NUL and newline bytes into the arguments after
// `lenslab`, parsed and validated by cli::CommandLine (every command's options and
// check_every_option) but not run. A refusal is a CLI::ParseError (fuzz/fuzz_argv_input.cpp,
// linked only by fuzz_argv and the replay test).
void parse_argv_input(std::string_view data);

}  // namespace lenslab::fuzz
