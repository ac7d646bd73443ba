#include "lensfile/lens_file_tokens.h"

#include <charconv>
#include <cmath>

#include "lensfile/lens_file_error.h"

namespace lenslab {

std::vector<std::string> lens_file_words(std::string_view line) {
    std::vector<std::string> words;
    size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (c == ' ' || c == '\t') {
            ++i;
            continue;
        }
        if (c == '"' || c == '\'') {
            const size_t end = line.find(c, i + 1);
            const size_t stop = end == std::string_view::npos ? line.size() : end;
            words.emplace_back(line.substr(i + 1, stop - i - 1));
            i = stop + 1;
            continue;
        }
        size_t end = i;
        while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
        words.emplace_back(line.substr(i, end - i));
        i = end;
    }
    return words;
}

double lens_file_number(const std::string& word, const std::string& file, int line,
                        const std::string& what) {
    double value = 0;
    const char* first = word.data();
    const char* last = word.data() + word.size();
    if (!word.empty() && *first == '+') ++first;  // from_chars takes no plus sign
    const auto [end, ec] = std::from_chars(first, last, value);
    if (word.empty() || ec != std::errc() || end != last || !std::isfinite(value)) {
        std::string message = what + ": '";
        message.append(word).append("' is not a number");
        if (ec == std::errc() && end != last) message += " (the line may be cut short)";
        throw LensFileError(file, line, message);
    }
    return value;
}

double lens_file_number_shifted(const std::string& word, int shift, const std::string& file,
                                int line, const std::string& what) {
    (void)lens_file_number(word, file, line, what);  // the word's own errors first
    const size_t e = word.find_first_of("eE");
    const int exponent = e == std::string::npos ? 0 : std::stoi(word.substr(e + 1));
    std::string shifted = word.substr(0, e);
    shifted.append("e").append(std::to_string(exponent + shift));
    return lens_file_number(shifted, file, line, what);
}

std::string lens_file_upper(std::string word) {
    for (char& c : word) {
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    }
    return word;
}

}  // namespace lenslab
