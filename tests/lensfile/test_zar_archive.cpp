// Zemax archives (.zar): the lens file packed in one is imported exactly as the file itself.
// The archives here are written by the test, in both header layouts, with an LZW packer
// written from the reader's description (lensfile/zar_archive.h); the reader was also
// checked by hand against three of Thorlabs' own archives (docs/scene-format.md).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <random>

#include "lensfile/lens_file_error.h"
#include "lensfile/lens_file_text.h"
#include "lensfile/zar_archive.h"
#include "scene/lens_file_import.h"

namespace lenslab {
namespace {

// Bits, most significant first, as the archive packs its codes.
class ZarBits {
public:
    void put(size_t code, int width) {
        for (int b = width - 1; b >= 0; --b) {
            if (m_used % 8 == 0) m_bytes.push_back(0);
            if ((code >> b) & 1u) m_bytes.back() = char(m_bytes.back() | (0x80 >> (m_used % 8)));
            ++m_used;
        }
    }
    const std::string& bytes() const { return m_bytes; }

private:
    std::string m_bytes;
    size_t m_used = 0;
};

// Codes at the widths the reader reads them: its dictionary holds 256 words, and one more
// per code read after the first; the width grows as soon as that fills it.
std::string zar_codes(const std::vector<size_t>& codes) {
    ZarBits bits;
    int width = 8;
    for (size_t k = 0; k < codes.size(); ++k) {
        if (256 + (k > 0 ? k - 1 : 0) >= (size_t(1) << width)) ++width;
        bits.put(codes[k], width);
    }
    return bits.bytes();
}

std::string pack_lzw(const std::string& text) {
    std::map<std::string, size_t> dictionary;
    for (int c = 0; c < 256; ++c) dictionary[std::string(1, char(c))] = size_t(c);
    std::vector<size_t> codes;
    std::string word;
    for (char c : text) {
        if (dictionary.count(word + c)) {
            word += c;
            continue;
        }
        codes.push_back(dictionary[word]);
        dictionary[word + c] = dictionary.size();
        word = std::string(1, c);
    }
    if (!word.empty()) codes.push_back(dictionary[word]);
    return zar_codes(codes);
}

// One packed file: the newer layout (version 0xEC, 0x288-byte header, UTF-16 name, 8-byte
// size) or the older (0xEA, 0x14C bytes, 8-bit name, 4-byte size).
std::string zar_entry(const std::string& name, const std::string& data, bool newer) {
    std::string header(newer ? 0x288 : 0x14C, '\0');
    header[0] = char(newer ? 0xEC : 0xEA);
    header[1] = char(0x03);
    const size_t size_at = newer ? 0x10 : 0x0C, size_bytes = newer ? 8 : 4;
    for (size_t i = 0; i < size_bytes; ++i)
        header[size_at + i] = char((data.size() >> (8 * i)) & 0xFF);
    for (size_t i = 0; i < name.size(); ++i) header[(newer ? 0x30 + 2 * i : 0x20 + i)] = name[i];
    return header + data;
}

std::filesystem::path write_file(const std::string& name, const std::string& bytes) {
    const auto dir = std::filesystem::temp_directory_path() / "lenslab_test_zar";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return dir / name;
}

TEST(ZarArchive, LzwUnpacksWhatWasPacked) {
    std::mt19937 random(7);
    std::string text;  // long enough for 9-, 10-, 11- and 12-bit codes, and repetitive runs
    for (int i = 0; i < 20000; ++i) text += "CURV DISZ GLAS N-BK7 0123456789\n"[random() % 33];
    for (const std::string& s :
         {std::string("a"), std::string("aaaaaaaaaaaaa"), std::string("abababababab"), text}) {
        EXPECT_EQ(unpack_zar_lzw(pack_lzw(s)), s) << s.substr(0, 20);
    }
}

TEST(ZarArchive, TheLensInsideImportsAsTheLensFile) {
    const std::string zmx_path = LENSLAB_TEST_DATA "/lensfile/data/cooke_triplet.zmx";
    const std::string zmx = read_lens_file_bytes(zmx_path);
    for (bool newer : {true, false}) {
        const std::string archive = zar_entry("COATING.DAT", "THORA 0.01\n", newer) +
                                    zar_entry("cooke_triplet.zmx.LZW", pack_lzw(zmx), !newer);
        const auto zar = write_file(newer ? "newer.zar" : "older.zar", archive);
        const std::vector<ZarEntry> entries = read_zar_archive(archive, zar.string());
        ASSERT_EQ(entries.size(), 2u);
        EXPECT_EQ(entries[0].name, "COATING.DAT");
        EXPECT_EQ(entries[1].name, "cooke_triplet.zmx");
        EXPECT_EQ(entries[1].data, zmx);
        EXPECT_EQ(import_lens_file(zar.string(), "triplet").group,
                  import_lens_file(zmx_path, "triplet").group);
    }
}

TEST(ZarArchive, BrokenArchivesAreRefusedWithTheReason) {
    const auto message = [](const std::string& bytes) {
        const auto path = write_file("broken.zar", bytes);
        try {
            (void)import_lens_file(path.string(), "lens");
        } catch (const LensFileError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::string entry = zar_entry("lens.zmx", "VERS 1\n", true);
    EXPECT_NE(message(entry.substr(0, 100)).find("ends inside its header"), std::string::npos);
    EXPECT_NE(message(entry.substr(0, entry.size() - 2)).find("ends before its 7 bytes"),
              std::string::npos);
    EXPECT_NE(message("PK\x03\x04 a zip file").find("not a Zemax archive"), std::string::npos);
    // Codes that each define a word one longer than the last: stopped, not unpacked.
    std::vector<size_t> runaway{'a'};
    for (size_t code = 256; code < 256 + 20000; ++code) runaway.push_back(code);
    EXPECT_NE(message(zar_entry("lens.zmx.LZW", zar_codes(runaway), true)).find("more than 64 MiB"),
              std::string::npos);
    EXPECT_NE(message(zar_entry("notes.txt", "hello", true))
                  .find("holds no .zmx file (it holds: notes.txt)"),
              std::string::npos);
}

}  // namespace
}  // namespace lenslab
