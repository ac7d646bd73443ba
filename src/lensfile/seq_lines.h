#pragma once
// The commands of a CODE V sequence file (.seq), line by line: comments ('!' to the end of the
// line, outside quotes) removed, a line ending in '&' joined with the next (CODE V's
// continuation), and each line split into its commands at ';'.

#include <string>
#include <vector>

namespace lenslab {

struct SeqLine {
    int line = 0;  // the first of the file's lines it is made of, for messages
    std::string text;
};

// The file's lines without comments, continuations joined.
std::vector<SeqLine> seq_logical_lines(const std::vector<std::string>& lines);

// `line` split into commands at ';' (outside quotes), a comment removed.
std::vector<std::string> seq_commands(const std::string& line);

}  // namespace lenslab
