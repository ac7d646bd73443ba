#pragma once
// The text of a lens file as lines of UTF-8. Zemax writes .zmx files in UTF-16 (little or
// big endian, after a byte order mark) or, in newer versions, UTF-8; CODE V .seq files are
// ASCII. A byte sequence that is no text in its encoding is refused with its line.

#include <string>
#include <vector>

namespace lenslab {

// The file's bytes; throws LensFileError (missing, unreadable, a directory, too large).
std::string read_lens_file_bytes(const std::string& path);

// `bytes` decoded to lines (without their line ends; CR LF, LF and CR all end a line).
// UTF-16 is recognised by its byte order mark, or without one by the zero high bytes of
// ASCII text. Throws LensFileError naming `file` and the line of an invalid sequence.
std::vector<std::string> decode_lens_file_lines(const std::string& bytes, const std::string& file);

}  // namespace lenslab
