#pragma once
// Zemax's archive (.zar), the form lens makers such as Thorlabs publish their lens files in:
// one or more packed files one after the other, each a fixed header (its format version in
// the first byte, its packed size, its name) and its bytes, LZW-compressed where the name
// ends in ".LZW" (variable code width from 9 bits, most significant bit first, a dictionary
// that grows without reset). The layout was learnt from the zmxtools project's reader.

#include <string>
#include <vector>

namespace lenslab {

struct ZarEntry {
    std::string name;  // as packed, without a ".LZW" suffix
    std::string data;  // unpacked
};

// The entries of the archive `bytes` (the file `file`, for errors). Throws LensFileError for
// a header of an unknown version or an entry cut short.
std::vector<ZarEntry> read_zar_archive(const std::string& bytes, const std::string& file);

// LZW as the archive packs it; exposed for the tests' archive writer to check against.
std::string unpack_zar_lzw(const std::string& packed);

}  // namespace lenslab
