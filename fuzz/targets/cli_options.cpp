// Fuzz target cli_options: the values of the command-line options that are text a user, a script or a
// web front end hands curvescan, through the very parsers and validators the commands use
// (tools/curvescan, linked in): render -l/--accept-language (an HTTP Accept-Language list),
// -w/-h/--left/--top/--page-width/--page-height (lengths with units), --files-from (the list of names,
// one a line: the bytes are the file), diff --ignore (x,y,w,h), text --features (OpenType feature
// lists), text --color/--background and render -b (CSS colours), and the number validators of every
// limit and scale option (kFiniteNumber, number_in_range over CLI11's conversion).
//
// The bytes are one option value, given to every parser. Each must return a value or an error, never
// crash; what a parser accepts must also be what the command relies on, else the target traps: tags of
// letters, digits, '-' and '*'; finite lengths; regions of non-negative size; non-empty names without a
// line break; feature values <= 65535; numbers a range validator passes inside its range.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "command_line_text.h"
#include "css_colour_option.h"
#include "feature_list.h"
#include "finite_number.h"
#include "fuzz_targets.h"
#include "option_range.h"

namespace curvescan::fuzz {
namespace {

bool is_tag_character(char c) noexcept {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '*';
}

/// Runs `validator` on a copy of `text` (a CLI11 validator may rewrite its argument); true when it passes.
bool passes(const CLI::Validator& validator, const std::string& text) {
  std::string value = text;
  return validator(value).empty();
}

}  // namespace

int fuzz_cli_options(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);  // bytes as characters

  if (const Result<std::vector<std::string>> tags = cli::parse_accept_language(text)) {
    for (const std::string& tag : *tags) {
      if (tag.empty()) __builtin_trap();
      for (const char c : tag) {
        if (!is_tag_character(c)) __builtin_trap();
      }
    }
  }
  for (const double dpi : {96.0, 1e-3, 1e6}) {  // the -d/-p range of render
    if (const Result<double> pixels = cli::command_line_length("--width", text, dpi)) {
      if (!std::isfinite(*pixels)) __builtin_trap();
    }
  }
  if (const Result<PixelBox> region = cli::parse_ignore_region(text)) {
    if (region->width < 0 || region->height < 0) __builtin_trap();
  }
  for (const std::string& name : cli::parse_name_list(text)) {
    // One '\r' before each '\n' is dropped (CRLF files); a name may still end in another one.
    if (name.empty() || name.find('\n') != std::string::npos) __builtin_trap();
  }
  if (const Result<std::vector<FontFeature>> features = cli::parse_feature_list(text)) {
    for (const FontFeature& feature : *features) {
      if (feature.value > 65535) __builtin_trap();
    }
  }
  (void)cli::css_colour_error(text);

  // The number validators, as the options chain them: a value kFiniteNumber and the range both pass must
  // convert to a number inside the range.
  const bool finite = passes(cli::kFiniteNumber, text);
  if (passes(cli::number_in_range(1e-9, 1e9), text)) {
    double value = 0.0;
    if (!CLI::detail::lexical_cast(text, value) || !(value >= 1e-9 && value <= 1e9)) __builtin_trap();
  }
  if (finite && !std::isfinite(std::stod(text))) __builtin_trap();  // it converted without throwing
  if (passes(cli::number_in_range(std::int64_t{1}, std::int64_t{1} << 31), text)) {
    std::int64_t value = 0;
    if (!CLI::detail::lexical_cast(text, value) || value < 1 || value > (std::int64_t{1} << 31))
      __builtin_trap();
  }
  (void)passes(cli::number_in_range(1u, 1024u), text);
  (void)passes(cli::number_in_range(std::size_t{1}, std::size_t{1} << 26), text);
  (void)passes(cli::one_of({"none", "default"}), text);
  return 0;
}

}  // namespace curvescan::fuzz
