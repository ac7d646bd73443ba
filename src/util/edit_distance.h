#pragma once
// The Levenshtein distance between two strings (insertions, deletions and substitutions of
// one character each cost 1), for "did you mean" suggestions: unknown scene keys, unknown
// glass names.

#include <cstddef>
#include <string>

namespace lenslab {

size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace lenslab
