// One fontconfig configuration per process (raster/text/fontconfig_config_p.h): font lookups and fallback
// share it instead of loading one each (a few milliseconds apiece, paid per document in a batch render), it
// follows FONTCONFIG_FILE when that changes, and lookups from several threads give the one-thread answers.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "curvescan/text/font_fallback.h"
#include "curvescan/text/font_lookup.h"
#include "font_files.h"
#include "scratch_directory.h"
#include "text/fontconfig_config_p.h"
#include "text/fontconfig_results_p.h"

using namespace curvescan;

namespace {

std::string matched_file(const std::string& family) {
  const Result<FontMatch> match = match_font(FontQuery{family, 400, false});
  REQUIRE(match.is_ok());
  return match->file;
}

// Sets an environment variable for the scope and restores its previous value (or its absence) after.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) previous_ = old;
    had_value_ = std::getenv(name) != nullptr;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnvironment() {
    if (had_value_) {
      setenv(name_, previous_.c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::string previous_;
  bool had_value_ = false;
};

}  // namespace

TEST_CASE("fontconfig: lookups and fallback share one configuration per process", "[font][fontconfig]") {
  const std::string first = matched_file("sans-serif");  // loads it, unless an earlier test did
  const int loads = detail::fontconfig_load_count();
  CHECK(loads >= 1);
  CHECK(matched_file("sans-serif") == first);
  CHECK(matched_file("Cantarell") != first);
  // A fallback's FcFontSort, for a character Cantarell lacks, uses the same configuration.
  Result<Font> cantarell = Font::open(kCantarellFile);
  REQUIRE(cantarell.is_ok());
  FontFallback fallback(*cantarell, FontQuery{"Cantarell", 400, false});
  REQUIRE(fallback.face_for(U'\u2660') != nullptr);  // ♠, from DejaVu Sans
  CHECK(detail::fontconfig_load_count() == loads);
}

TEST_CASE("fontconfig: a changed FONTCONFIG_FILE loads that configuration, a fallback keeps its own",
          "[font][fontconfig]") {
  const std::string tests_answer = matched_file("sans-serif");
  Result<Font> cantarell = Font::open(kCantarellFile);
  REQUIRE(cantarell.is_ok());
  FontFallback fallback(*cantarell, FontQuery{"Cantarell", 400, false});
  REQUIRE(fallback.face_for(U'\u2660') != nullptr);  // its candidates come from the tests' configuration
  const int loads = detail::fontconfig_load_count();
  {
    // A configuration whose only font is the colour test font: every family resolves to it.
    const auto dir = test::scratch_directory("fontconfig-config");
    const std::filesystem::path font =
        std::filesystem::path(CURVESCAN_SOURCE_DIR) / "tests/fonts/CurvescanColourTest.ttf";
    std::filesystem::create_directories(dir / "fonts");
    std::filesystem::copy_file(font, dir / "fonts" / font.filename());
    std::ofstream(dir / "fonts.conf")
        << "<?xml version=\"1.0\"?>\n<fontconfig><dir>" << (dir / "fonts").string() << "</dir><cachedir>"
        << (dir / "cache").string() << "</cachedir></fontconfig>\n";
    const ScopedEnvironment environment("FONTCONFIG_FILE", (dir / "fonts.conf").string());
    CHECK(matched_file("sans-serif") == (dir / "fonts" / font.filename()).string());
    CHECK(detail::fontconfig_load_count() == loads + 1);
    // The fallback made under the tests' configuration still answers from it (its character sets live in
    // that configuration's caches, which its share keeps).
    CHECK(fallback.face_for(U'\u2500') != nullptr);  // ─, from DejaVu Sans
  }
  CHECK(matched_file("sans-serif") == tests_answer);
  CHECK(detail::fontconfig_load_count() == loads + 2);
}

TEST_CASE("fontconfig: lookups from several threads give the one-thread answers", "[font][fontconfig]") {
  const std::vector<std::string> families{"sans-serif", "serif", "monospace", "Cantarell"};
  std::vector<std::string> expected;
  for (const std::string& family : families) expected.push_back(matched_file(family));
  constexpr int kThreads = 4, kRounds = 20;
  std::vector<std::vector<std::string>> answers(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int round = 0; round < kRounds; ++round) {
        const std::string& family = families[static_cast<std::size_t>(round + t) % families.size()];
        const Result<FontMatch> match = match_font(FontQuery{family, 400, false});
        answers[static_cast<std::size_t>(t)].push_back(match ? match->file : "error");
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) {
    for (int round = 0; round < kRounds; ++round) {
      INFO("thread " << t << ", round " << round);
      CHECK(answers[static_cast<std::size_t>(t)][static_cast<std::size_t>(round)] ==
            expected[static_cast<std::size_t>(round + t) % families.size()]);
    }
  }
}

// fontconfig_results_p.h: each request (family list, weight, slant, width) is asked of fontconfig once per
// process; every later document's lookup and fallback is answered from what was kept.
TEST_CASE("fontconfig: a match or a sort is asked of fontconfig once per request and process",
          "[font][fontconfig]") {
  // A weight no other test asks for, so the first lookup here is fontconfig's.
  const FontQuery query{"Cantarell", 531, false};
  const int before = detail::fontconfig_request_count();
  const Result<FontMatch> first = match_font(query);
  REQUIRE(first.is_ok());
  CHECK(detail::fontconfig_request_count() == before + 1);
  const Result<FontMatch> again = match_font(query);
  REQUIRE(again.is_ok());
  CHECK(detail::fontconfig_request_count() == before + 1);
  CHECK(again->file == first->file);
  CHECK(again->family == first->family);
  CHECK(again->family_found == first->family_found);
  // Another slant, width or family list is another request.
  CHECK(match_font(FontQuery{"Cantarell", 531, true}).is_ok());
  CHECK(detail::fontconfig_request_count() == before + 2);
  CHECK(match_font(FontQuery{"Cantarell", 531, false, 75.0}).is_ok());
  CHECK(detail::fontconfig_request_count() == before + 3);
  CHECK(match_font(FontQuery{"Cantarell, DejaVu Sans", 531, false}).is_ok());
  CHECK(detail::fontconfig_request_count() == before + 4);

  // Two fallbacks for the same request, as two documents make: one FcFontSort, the same answers.
  Result<Font> cantarell = Font::open(kCantarellFile);
  REQUIRE(cantarell.is_ok());
  FontFallback first_document(*cantarell, query);
  const Font* spade = first_document.face_for(U'\u2660');  // ♠, from DejaVu Sans
  REQUIRE(spade != nullptr);
  CHECK(detail::fontconfig_request_count() == before + 5);
  FontFallback second_document(*cantarell, query);
  const Font* spade_again = second_document.face_for(U'\u2660');
  REQUIRE(spade_again != nullptr);
  CHECK(detail::fontconfig_request_count() == before + 5);
  CHECK(spade_again->family_name() == spade->family_name());
  CHECK(spade_again != spade);  // each object opens its own faces
  // The same character set answers for a character no candidate has, in both.
  CHECK(first_document.face_for(U'\U0010FFFD') == nullptr);
  CHECK(second_document.face_for(U'\U0010FFFD') == nullptr);
}

TEST_CASE("fontconfig: kept answers are those of the configuration in force", "[font][fontconfig]") {
  const FontQuery query{"sans-serif", 532, false};
  const std::string tests_answer = match_font(query)->file;
  const auto dir = test::scratch_directory("fontconfig-results");
  const std::filesystem::path font =
      std::filesystem::path(CURVESCAN_SOURCE_DIR) / "tests/fonts/CurvescanColourTest.ttf";
  std::filesystem::create_directories(dir / "fonts");
  std::filesystem::copy_file(font, dir / "fonts" / font.filename());
  std::ofstream(dir / "fonts.conf") << "<?xml version=\"1.0\"?>\n<fontconfig><dir>"
                                    << (dir / "fonts").string() << "</dir><cachedir>"
                                    << (dir / "cache").string() << "</cachedir></fontconfig>\n";
  {
    const ScopedEnvironment environment("FONTCONFIG_FILE", (dir / "fonts.conf").string());
    // The same request, asked again of the other configuration: its one font.
    const int before = detail::fontconfig_request_count();
    const Result<FontMatch> other = match_font(query);
    REQUIRE(other.is_ok());
    CHECK(other->file == (dir / "fonts" / font.filename()).string());
    CHECK(detail::fontconfig_request_count() == before + 1);
  }
  CHECK(match_font(query)->file == tests_answer);
}

TEST_CASE("fontconfig: fallbacks on several threads share one sorted list and give the one-thread answers",
          "[font][fontconfig]") {
  const FontQuery query{"Cantarell", 533, false};  // a weight of this test's own: the first sort is here
  Result<Font> reference_primary = Font::open(kCantarellFile);
  REQUIRE(reference_primary.is_ok());
  FontFallback reference(*reference_primary, query);
  const std::vector<char32_t> characters{U'\u2660', U'\u2500', U'\u25a0', U'\U0010FFFD'};
  std::vector<std::string> expected;
  for (const char32_t c : characters) {
    const Font* face = reference.face_for(c);
    expected.push_back(face != nullptr ? face->family_name() : "none");
  }
  const int sorts = detail::fontconfig_request_count();
  constexpr int kThreads = 4;
  std::vector<std::vector<std::string>> answers(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      Result<Font> primary = Font::open(kCantarellFile);  // a Font serves one thread
      if (!primary) return;
      for (int round = 0; round < 10; ++round) {
        FontFallback fallback(*primary, query);  // a document of its own each round
        for (const char32_t c : characters) {
          const Font* face = fallback.face_for(c);
          answers[static_cast<std::size_t>(t)].push_back(face != nullptr ? face->family_name() : "none");
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  CHECK(detail::fontconfig_request_count() == sorts);  // no thread asked fontconfig again
  for (int t = 0; t < kThreads; ++t) {
    REQUIRE(answers[static_cast<std::size_t>(t)].size() == 10 * characters.size());
    for (std::size_t i = 0; i < answers[static_cast<std::size_t>(t)].size(); ++i) {
      INFO("thread " << t << ", answer " << i);
      CHECK(answers[static_cast<std::size_t>(t)][i] == expected[i % characters.size()]);
    }
  }
}
