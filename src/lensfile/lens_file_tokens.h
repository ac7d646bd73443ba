#pragma once
// Reading the words and numbers of one line of a lens file, with errors naming the line.

#include <string>
#include <string_view>
#include <vector>

namespace lenslab {

// The words of `line`, split at blanks; a 'quoted text' or "quoted text" is one word
// (without its quotes).
std::vector<std::string> lens_file_words(std::string_view line);

// `word` as a finite number, the whole word (no trailing text); throws LensFileError at `line`
// saying what `what` is ("CURV's curvature").
double lens_file_number(const std::string& word, const std::string& file, int line,
                        const std::string& what);

// `word` as a number times 10^shift, read as one decimal number ("0.5875618" with shift 3 is
// exactly 587.5618, where 1000 * 0.5875618 is not). Errors as lens_file_number.
double lens_file_number_shifted(const std::string& word, int shift, const std::string& file,
                                int line, const std::string& what);

// `word` in upper case (ASCII).
std::string lens_file_upper(std::string word);

}  // namespace lenslab
