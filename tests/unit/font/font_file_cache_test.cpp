// Font files read once per process while they stay the same (text/font_file_cache_p.h): two Fonts of one
// unchanged file share its bytes, and a file replaced or cut on disk is read again, so its new content —
// or its new error — is what the next Font sees.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "curvescan/text/font.h"
#include "font_files.h"
#include "scratch_directory.h"
#include "text/font_face_p.h"
#include "text/font_file_cache_p.h"

using namespace curvescan;

namespace {

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST_CASE("font file cache: two Fonts of one unchanged file share its bytes", "[font][cache]") {
  const Result<Font> first = Font::open(kDejaVuSansFile);
  const Result<Font> second = Font::open(kDejaVuSansFile);
  REQUIRE(first.is_ok());
  REQUIRE(second.is_ok());
  CHECK(first->impl().bytes == second->impl().bytes);  // the same shared vector, not a second read
  CHECK(first->impl().bytes->size() == std::filesystem::file_size(kDejaVuSansFile));
  CHECK(detail::cached_font_file_bytes() >= first->impl().bytes->size());
  CHECK(detail::cached_font_file_bytes() <= detail::kMaxCachedFontFileBytes);
  // Glyphs still come out of a shared face as from its own.
  CHECK(second->glyph_for(U'H') == first->glyph_for(U'H'));
}

TEST_CASE("font file cache: a file replaced, or cut, on disk is read again", "[font][cache]") {
  const test::ScratchDirectory scratch("font-cache");
  const std::filesystem::path path = scratch / "font.ttf";
  const std::string dejavu = file_bytes(kDejaVuSansFile);
  const std::string cantarell = file_bytes(kCantarellFile);
  write_file(path, dejavu);
  const Result<Font> before = Font::open(path);
  REQUIRE(before.is_ok());
  CHECK(before->family_name() == "DejaVu Sans");

  // Another font written over it: another size (and another modification time) -> another key.
  write_file(path, cantarell);
  const Result<Font> replaced = Font::open(path);
  REQUIRE(replaced.is_ok());
  CHECK(replaced->family_name() == "Cantarell");
  CHECK(replaced->impl().bytes != before->impl().bytes);
  // The earlier Font keeps its own bytes alive and still works.
  CHECK(before->glyph_for(U'H') != 0);

  // Cut to 2000 bytes: the cached copy of the whole file must not hide the damage.
  write_file(path, cantarell.substr(0, 2000));
  const Result<Font> cut = Font::open(path);
  REQUIRE_FALSE(cut.is_ok());
  CHECK(cut.error().kind == ErrorKind::kCorruptInput);
  CHECK(cut.error().message.find("(2000 bytes)") != std::string::npos);
}

TEST_CASE("font file cache: threads opening one file at once get one copy and working faces",
          "[font][cache]") {
  constexpr int kThreads = 4;
  std::vector<detail::FontFileBytes> seen(kThreads);
  std::vector<GlyphId> glyphs(kThreads, 0);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&seen, &glyphs, i] {
      const Result<Font> font = Font::open(kCantarellFile);
      if (!font) return;
      seen[static_cast<std::size_t>(i)] = font->impl().bytes;
      glyphs[static_cast<std::size_t>(i)] = font->glyph_for(U'a');
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < kThreads; ++i) {
    INFO(i);
    REQUIRE(seen[static_cast<std::size_t>(i)] != nullptr);
    CHECK(seen[static_cast<std::size_t>(i)] == seen[0]);
    CHECK(glyphs[static_cast<std::size_t>(i)] != 0);
  }
}
