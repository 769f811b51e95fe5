// Font loading, outline formats, glyph paths and fontconfig lookup.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "curvescan/text/font.h"
#include "curvescan/text/font_lookup.h"
#include "font_files.h"
#include "scratch_directory.h"

using namespace curvescan;

namespace {

int count_verbs(const Path& path, PathVerb verb) {
  int n = 0;
  for (const PathVerb v : path.verbs()) n += v == verb ? 1 : 0;
  return n;
}

// Writes `bytes` to `name` in `dir`.
std::filesystem::path scratch_file(const test::ScratchDirectory& dir, const std::string& name,
                                   const std::string& bytes) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

}  // namespace

TEST_CASE("font: DejaVu Sans is TrueType (quads), Cantarell is CFF (cubics)", "[font]") {
  const Result<Font> dejavu = Font::open(kDejaVuSansFile);
  REQUIRE(dejavu.is_ok());
  CHECK(dejavu->outline_format() == OutlineFormat::kTrueType);
  CHECK(dejavu->family_name() == "DejaVu Sans");
  const Result<Path> o = dejavu->glyph_path(dejavu->glyph_for(U'o'));
  REQUIRE(o.is_ok());
  CHECK(count_verbs(*o, PathVerb::kQuad) > 0);
  CHECK(count_verbs(*o, PathVerb::kCubic) == 0);
  CHECK(count_verbs(*o, PathVerb::kMove) == 2);  // outer and inner contour
  CHECK(count_verbs(*o, PathVerb::kClose) == 2);

  const Result<Font> cantarell = Font::open(kCantarellFile);
  REQUIRE(cantarell.is_ok());
  CHECK(cantarell->outline_format() == OutlineFormat::kCff);
  const Result<Path> c_o = cantarell->glyph_path(cantarell->glyph_for(U'o'));
  REQUIRE(c_o.is_ok());
  CHECK(count_verbs(*c_o, PathVerb::kCubic) > 0);
  CHECK(count_verbs(*c_o, PathVerb::kQuad) == 0);
}

TEST_CASE("font: glyph paths are the font-unit outline mapped by the transform", "[font]") {
  const Result<Font> font = Font::open(kDejaVuSansFile);
  REQUIRE(font.is_ok());
  const GlyphId h = font->glyph_for(U'H');
  // The unscaled control box straight from FreeType.
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  REQUIRE(FT_Init_FreeType(&library) == 0);
  REQUIRE(FT_New_Face(library, kDejaVuSansFile, 0, &face) == 0);
  REQUIRE(FT_Load_Glyph(face, h, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
  FT_BBox box;
  FT_Outline_Get_CBox(&face->glyph->outline, &box);
  FT_Done_Face(face);
  FT_Done_FreeType(library);

  const Affine transform{0.5, 0.0, 0.0, -0.5, 100.0, 200.0};
  const Result<Path> path = font->glyph_path(h, transform);
  REQUIRE(path.is_ok());
  const Rect bounds = path->bounds();
  // Font-unit integers times 0.5 plus integers: exact in double.
  CHECK(bounds.x0 == 100.0 + 0.5 * static_cast<double>(box.xMin));
  CHECK(bounds.x1 == 100.0 + 0.5 * static_cast<double>(box.xMax));
  CHECK(bounds.y0 == 200.0 - 0.5 * static_cast<double>(box.yMax));
  CHECK(bounds.y1 == 200.0 - 0.5 * static_cast<double>(box.yMin));
}

TEST_CASE("font: a space has no outline — a glyph index outside the face is an error", "[font]") {
  const Result<Font> font = Font::open(kDejaVuSansFile);
  REQUIRE(font.is_ok());
  const Result<Path> space = font->glyph_path(font->glyph_for(U' '));
  REQUIRE(space.is_ok());
  CHECK(space->empty());
  const Result<Path> outside = font->glyph_path(static_cast<GlyphId>(font->glyph_count()));
  REQUIRE_FALSE(outside.is_ok());
  CHECK(outside.error().kind == ErrorKind::kInvalidArgument);
  CHECK(font->advance(static_cast<GlyphId>(font->glyph_count())) == 0.0);
  CHECK(font->glyph_for(U'\U0010FFFD') == kNotdefGlyph);
}

TEST_CASE("font: a missing file, an empty file and a corrupt file fail with a message", "[font]") {
  const Result<Font> missing = Font::open("/nonexistent/font.ttf");
  REQUIRE_FALSE(missing.is_ok());
  CHECK(missing.error().kind == ErrorKind::kIoError);
  CHECK(missing.error().message.find("/nonexistent/font.ttf") != std::string::npos);

  const auto scratch = test::scratch_directory("font-test");
  const Result<Font> empty = Font::open(scratch_file(scratch, "empty.ttf", ""));
  REQUIRE_FALSE(empty.is_ok());
  CHECK(empty.error().kind == ErrorKind::kCorruptInput);

  const Result<Font> text =
      Font::open(scratch_file(scratch, "text.ttf", "this is not a font, just some text\n"));
  REQUIRE_FALSE(text.is_ok());
  CHECK(text.error().kind == ErrorKind::kCorruptInput);

  // A real font cut in half: FreeType's table directory points past the end.
  std::ifstream in(kDejaVuSansFile, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Result<Font> truncated = Font::open(scratch_file(scratch, "truncated.ttf", bytes.substr(0, 2000)));
  REQUIRE_FALSE(truncated.is_ok());
  CHECK(truncated.error().kind == ErrorKind::kCorruptInput);
  CHECK(truncated.error().message.find("truncated or corrupt") != std::string::npos);
  CHECK(truncated.error().message.find("(2000 bytes)") != std::string::npos);

  // A device is refused by its type, unread (reading /dev/zero would only stop at the size limit).
  if (std::filesystem::exists("/dev/zero")) {
    const Result<Font> device = Font::open("/dev/zero");
    REQUIRE_FALSE(device.is_ok());
    CHECK(device.error().kind == ErrorKind::kInvalidArgument);
    CHECK(device.error().message.find("is not a font file: it is a character device") != std::string::npos);
  }
}

TEST_CASE("font lookup: family names, weights, generic families and fallback", "[font][fontconfig]") {
  const Result<FontMatch> regular = match_font({"DejaVu Sans", 400, false});
  REQUIRE(regular.is_ok());
  CHECK(regular->family_found);
  CHECK(regular->family == "DejaVu Sans");
  CHECK(regular->file.filename() == "DejaVuSans.ttf");

  const Result<FontMatch> bold = match_font({"dejavu sans", 700, false});
  REQUIRE(bold.is_ok());
  CHECK(bold->family_found);  // family names compare case-insensitively (CSS Fonts 3 section 5.2)
  CHECK(bold->file.filename() == "DejaVuSans-Bold.ttf");

  const Result<FontMatch> list = match_font({"No Such Family 12345, 'Cantarell', serif", 400, false});
  REQUIRE(list.is_ok());
  CHECK(list->family_found);
  CHECK(list->family == "Cantarell");

  const Result<FontMatch> unknown = match_font({"No Such Family 12345", 400, false});
  REQUIRE(unknown.is_ok());
  CHECK_FALSE(unknown->family_found);
  const Result<Font> strict = load_font({"No Such Family 12345", 400, false}, /*allow_fallback=*/false);
  REQUIRE_FALSE(strict.is_ok());
  CHECK(strict.error().message.find("No Such Family 12345") != std::string::npos);
  const Result<Font> fallback = load_font({"No Such Family 12345", 400, false}, /*allow_fallback=*/true);
  CHECK(fallback.is_ok());

  CHECK_FALSE(match_font({" , ", 400, false}).is_ok());
}
