#include "lensfile/seq_lines.h"

namespace lenslab {

namespace {

// A line without its comment ('!' to the end, outside quotes).
std::string seq_uncommented(const std::string& line) {
    char quote = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '!') {
            return line.substr(0, i);
        }
    }
    return line;
}

}  // namespace

std::vector<SeqLine> seq_logical_lines(const std::vector<std::string>& lines) {
    std::vector<SeqLine> out;
    bool continued = false;
    for (size_t i = 0; i < lines.size(); ++i) {
        std::string text = seq_uncommented(lines[i]);
        const size_t last = text.find_last_not_of(" \t");
        const bool goes_on = last != std::string::npos && text[last] == '&';
        if (goes_on) text.erase(last);
        if (continued) {
            out.back().text.append(" ").append(text);
        } else {
            out.push_back({static_cast<int>(i) + 1, text});
        }
        continued = goes_on;
    }
    return out;
}

std::vector<std::string> seq_commands(const std::string& line) {
    std::vector<std::string> out(1);
    char quote = 0;
    for (const char c : line) {
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '!') {
            break;
        } else if (c == ';') {
            out.emplace_back();
            continue;
        }
        out.back() += c;
    }
    return out;
}

}  // namespace lenslab
