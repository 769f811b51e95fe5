// `curvescan text` on bad input: font files cut short or with corrupted tables (a system font copied into
// the test, never committed), wrong file types, bad UTF-8, absurd sizes and every limit. Each: the exit
// code and message of the table, no crash, and no output file after a failure (bad_input_case.h).
#include <cstdint>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bad_input_case.h"

namespace curvescan::test {
namespace {

constexpr const char* kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct TableRecord {
  std::size_t record_offset;  // where the table's 16-byte record sits in the table directory
  std::uint32_t offset;
  std::uint32_t length;
};

std::uint32_t be32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) value = (value << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return value;
}

// The sfnt table directory (OpenType specification, "Organization of an OpenType font": numTables at 4,
// 16-byte records from 12: tag, checksum, offset, length).
std::map<std::string, TableRecord> table_directory(const std::string& font) {
  std::map<std::string, TableRecord> tables;
  const std::size_t count = (static_cast<std::size_t>(static_cast<std::uint8_t>(font[4])) << 8) |
                            static_cast<std::uint8_t>(font[5]);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t record = 12 + 16 * i;
    tables[font.substr(record, 4)] = {record, be32(font, record + 8), be32(font, record + 12)};
  }
  return tables;
}

// The font with `table`'s offset pointing far beyond the end of the file.
std::string with_table_beyond_end(std::string font, const std::string& table) {
  const TableRecord record = table_directory(font).at(table);
  for (std::size_t i = 0; i < 4; ++i) font[record.record_offset + 8 + i] = static_cast<char>(i == 3 ? 0x00 : 0x7f);
  return font;
}

// The font with the first 4096 bytes of `table` replaced by seeded garbage.
std::string with_table_garbage(std::string font, const std::string& table, unsigned seed) {
  const TableRecord record = table_directory(font).at(table);
  std::mt19937 random(seed);
  const std::size_t end = std::min<std::size_t>(record.offset + std::min<std::uint32_t>(record.length, 4096), font.size());
  for (std::size_t i = record.offset; i < end; ++i) font[i] = static_cast<char>(random() & 0xff);
  return font;
}

TEST_CASE("text: cut and corrupted font files are an error or drawn with warnings, never a crash", "[bad_input][text]") {
  if (!std::filesystem::exists(kDejaVuSans)) {
    WARN("skipped: " << kDejaVuSans << " is not installed");
    return;
  }
  const std::string font = read_text(kDejaVuSans);
  const std::string kNotAFont = "'[^']*font.ttf' is not a font file FreeType can read";
  // A cut sfnt file is named as such before FreeType sees it (font.cpp, sfnt_truncation).
  const std::string kTruncated = "'[^']*font.ttf' is truncated or corrupt: ";
  std::vector<BadInputCase> cases;
  const auto add = [&](const std::string& name, const std::string& input, int exit_code, const std::string& message) {
    BadInputCase c{name, "text Hello --font {in} -o {out}", input, exit_code, message};
    c.input_name = "font.ttf";
    cases.push_back(c);
  };
  add("empty font file", "", 3, kNotAFont);
  for (const std::size_t cut : {std::size_t{4}, std::size_t{12}, std::size_t{100}}) {
    add("font cut after " + std::to_string(cut) + " bytes", font.substr(0, cut), 3,
        kTruncated + "the table directory is cut short");
  }
  // Cut after the table directory: a table runs past the end (before, FreeType opened some of these and
  // drew nothing, as it reads glyf lazily).
  for (const std::size_t cut : {std::size_t{1000}, font.size() / 2, font.size() - 1}) {
    add("font cut after " + std::to_string(cut) + " bytes", font.substr(0, cut), 3,
        kTruncated + "its '[A-Za-z/ ]{4}' table \\(bytes [0-9]+ to [0-9]+\\) runs past the end of the file \\(" +
            std::to_string(cut) + " bytes\\)");
  }
  add("no tables (numTables 0)", font.substr(0, 4) + std::string(2, '\0') + font.substr(6), 3, kNotAFont);
  // Every table pointing past the end is named, glyf and cmap included (FreeType reads those lazily, so
  // the face used to open and draw nothing or .notdef boxes).
  for (const char* table : {"head", "hhea", "loca", "maxp", "glyf", "cmap"}) {
    add(std::string("'") + table + "' beyond the end of the file", with_table_beyond_end(font, table), 3,
        kTruncated + "its '" + table + "' table");
  }
  unsigned seed = 100;
  for (const char* table : {"glyf", "loca", "cmap", "hmtx", "GSUB", "GPOS", "kern"}) {
    add(std::string("seeded garbage in '") + table + "'", with_table_garbage(font, table, ++seed), 0, "^$|warning");
  }
  add("an SVG file named .ttf", R"(<svg xmlns="http://www.w3.org/2000/svg"/>)", 3, kNotAFont);
  add("a PNG signature named .ttf", std::string("\x89PNG\r\n\x1a\n", 8) + std::string(64, '\0'), 3, kNotAFont);
  add("a collection header and nothing else", "ttcf" + std::string(8, '\0'), 3, kNotAFont);
  BadInputCase directory{"font path is a directory", "text Hello --font {in} -o {out}", "", 3,
                         "cannot read '[^']*font.ttf': it is a directory", InputKind::kDirectory};
  directory.input_name = "font.ttf";
  cases.push_back(directory);
  BadInputCase missing{"missing font file", "text Hello --font {in} -o {out}", "", 3,
                       "font file '[^']*font.ttf' does not exist", InputKind::kMissing};
  missing.input_name = "font.ttf";
  cases.push_back(missing);
  if (std::filesystem::exists("/dev/zero")) {
    // It exists: not "does not exist", and not read at all.
    cases.push_back({"--font /dev/zero", "text Hello --font /dev/zero -o {out}", "", 3,
                     "'/dev/zero' is not a font file: it is a character device"});
  }
  run_bad_inputs(cases);
}

// `count` distinct characters from U+100000 on (supplementary private use area B), as UTF-8.
std::string plane_16_private_use(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    const auto c = static_cast<std::uint32_t>(0x100000 + i);
    text += static_cast<char>(0xF0 | (c >> 18));
    text += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    text += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    text += static_cast<char>(0x80 | (c & 0x3F));
  }
  return text;
}

TEST_CASE("text: bad text, absurd sizes and every limit are one clear error", "[bad_input][text][limits]") {
  if (!std::filesystem::exists(kDejaVuSans)) {
    WARN("skipped: " << kDejaVuSans << " is not installed");
    return;
  }
  const std::string with_font = std::string(" --font ") + kDejaVuSans + " -o {out}";
  const std::string from_file = "text -i {in}" + with_font;
  const std::string hello = "text Hello" + with_font;
  std::vector<BadInputCase> cases = {
      {"empty text file", from_file, "", 3,
       "the text of '[^']*input' is empty \\(a final line break is not drawn\\)"},
      {"seeded binary garbage", from_file, std::string("\xff\xfe", 2) + "abc", 3,
       "the text of '[^']*input' is not valid UTF-8: byte 0xFF at offset 0 \\(the 1st byte\\) never occurs "
       "in "
       "UTF-8; it starts with a UTF-16 byte order mark: convert it with iconv -f UTF-16 -t UTF-8"},
      {"a UTF-16 surrogate in UTF-8", from_file, "\xed\xa0\x80", 3, "not valid UTF-8"},
      {"an overlong UTF-8 form", from_file, "\xc0\xaf", 3, "not valid UTF-8"},
      {"cut inside a UTF-8 character", from_file, "ok \xe2\x82", 3, "not valid UTF-8"},
      {"NUL and control characters: drawn as .notdef", from_file, std::string("a\0b\x01\x7f", 5), 0,
       "no glyph for U\\+0000 in"},
      // 300 characters no font has (plane 16 private use): the first 100 named, the rest counted on one line.
      {"300 characters without a glyph: 100 named, then a count", from_file, plane_16_private_use(300), 0,
       // (A plain pattern: std::regex recurses once per character a repetition matches, and a pattern
       // spanning the 100 warning lines overflowed the stack under AddressSanitizer.) 300 - 200 = 100 named.
       "warning: 200 more characters have no glyph either \\(not listed\\)"},
      {"text file is a directory", from_file, "", 3, "cannot read '[^']*input': it is a directory",
       InputKind::kDirectory},
      {"missing text file", from_file, "", 3, "cannot open '[^']*input'", InputKind::kMissing},
      {"--size NaN", "text x --size nan" + with_font, "", 64,
       "--size: the value 'nan' is not a finite number"},
      {"--size 1e400", "text x --size 1e400" + with_font, "", 64,
       "--size: the value '1e400' is not a finite"},
      {"--size -0", "text x --size -0" + with_font, "", 64,
       "--size: '-0' is out of range: give a number more than 0 and at most 32767"},
      {"--size -20", "text x --size -20" + with_font, "", 64,
       "--size: '-20' is out of range: give a number more than 0 and at most 32767"},
      {"--size 1e9", "text x --size 1e9" + with_font, "", 64,
       "--size: '1e9' is out of range: give a number more than 0 and at most 32767"},
      {"text and -i both: a usage error", "text x -i {in}" + with_font, "x", 64, "excludes"},
      {"--margin 1e400", "text x --margin 1e400" + with_font, "", 64, "--margin"},
      {"--line-height inf", "text x --line-height inf" + with_font, "", 64, "--line-height"},
      // A side beyond 32767: --max-pixels cannot help, and the message does not say it would.
      {"a huge --size: the side limit", "text x --size 30000" + with_font, "", 3,
       "the text at --size 30000 with margins of 7500 pixels needs [0-9]+ x [0-9]+ pixels, beyond the limit "
       "of "
       "32767 pixels per side \\(use a smaller --size, --margin or --line-height, or fewer lines\\)"},
      {"5000 characters on one line: the side limit", from_file, std::string(5000, 'W'), 3,
       "needs [0-9]+ x [0-9]+ pixels, beyond the limit of 32767 pixels per side \\(use a smaller --size, "
       "--margin or "
       "--line-height, or shorter lines\\)"},
      {"--max-pixels", hello + " --max-pixels 100", "", 3,
       "the text at --size 32 with margins of 8 pixels needs [0-9]+ x [0-9]+ pixels, [0-9]+ in all, beyond "
       "the "
       "limit of 100 pixels \\(raise --max-pixels, up to 67108864, or use a smaller --size or --margin\\)"},
      {"--width and --height beyond --max-pixels", hello + " --width 30000 --height 30000", "", 3,
       "--width and --height ask for 30000 x 30000 pixels, 900000000 in all, beyond the limit of 16777216 "
       "pixels "
       "\\(--max-pixels goes up to 67108864; use a smaller --width or --height\\)"},
      {"--max-segments", hello + " --max-segments 10", "", 3,
       "flattens to more than 10 line segments, the segment limit per render \\(raise --max-segments\\)"},
      {"--max-memory", hello + " --width 1000 --height 1000 --max-memory 1", "", 3,
       "a 1000 x 1000 canvas and the text's outlines need [45] MiB, beyond the memory limit of 1 MiB per "
       "render "
       "\\(raise --max-memory\\)"},
      // 10^6 characters: refused before the layout is made (256 bytes a character, cmd_text.cpp).
      {"10^6 characters under --max-memory 16", from_file + " --max-memory 16", std::string(1'000'000, 'a'),
       3,
       "laying out 1000000 characters needs 245 MiB, beyond the memory limit of 16 MiB per render "
       "\\(raise --max-memory\\)"},
      // 40 000 characters pass the layout check (10 MiB) but not the outlines' ('@' is about 1 KiB of
      // points, counted three times while building: over 100 MiB): refused before they are built.
      {"the outlines of 40000 characters under --max-memory 16",
       from_file + " --max-memory 16 --width 100 --height 100", std::string(40'000, '@'), 3,
       "the outlines of 40000 glyphs need [0-9]+ MiB to build, beyond the memory limit of 16 MiB per render "
       "\\(raise --max-memory\\)"},
      {"--max-text-length, text as an argument", "text abcdefghijk --max-text-length 10" + with_font, "", 3,
       "the text has 11 characters, above the text length limit of 10 \\(raise --max-text-length\\)"},
      {"--max-text-length, text from a file", from_file + " --max-text-length 10", std::string(100, 'a'), 3,
       "has more than 10 characters, the text length limit \\(raise --max-text-length\\)"},
      {"--max-input-size", from_file + " --max-input-size 1", std::string(std::size_t{3} << 19, 'a'), 3,
       "larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"},
      {"text from /dev/zero on standard input past --max-input-size 1",
       "text -i - --max-input-size 1 --font " + std::string(kDejaVuSans) + " -o {out} < /dev/zero", "", 3,
       "input '<stdin>' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"},
      {"output in a missing directory",
       "text Hello --font " + std::string(kDejaVuSans) + " -o {dir}/missing/out.png", "", 3, "cannot write"},
      {"output path is a directory", "text Hello --font " + std::string(kDejaVuSans) + " -o {dir}", "", 3,
       "cannot write"},
  };
  // -i from a FIFO offering 3 MiB stops at the 1 MiB bound.
  BadInputCase fifo{"text from a FIFO offering 3 MiB past --max-input-size 1", from_file + " --max-input-size 1", "", 3,
                    "input '[^']*input' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)",
                    InputKind::kFifo};
  fifo.fifo_bytes = std::size_t{3} << 20;
  cases.push_back(fifo);
  run_bad_inputs(cases);
}

}  // namespace
}  // namespace curvescan::test
