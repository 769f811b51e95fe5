// SVG <text> layout (text_element.h).
#include "text_element.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "css/syntax.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/length.h"
#include "curvescan/svg/number.h"
#include "curvescan/text/text_layout.h"
#include "curvescan/text/utf8.h"
#include "text_whitespace.h"

namespace curvescan::svg::detail {
namespace {

std::string_view local_name_of(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

// Attributes and properties of SVG text this renderer does not implement: noted, not errors.
constexpr std::array<std::string_view, 17> kUnsupported{"rotate",
                                                        "textLength",
                                                        "lengthAdjust",
                                                        "writing-mode",
                                                        "baseline-shift",
                                                        "dominant-baseline",
                                                        "alignment-baseline",
                                                        "letter-spacing",
                                                        "word-spacing",
                                                        "text-decoration",
                                                        "font-variant",
                                                        "font-stretch",
                                                        "direction",
                                                        "unicode-bidi",
                                                        "kerning",
                                                        "glyph-orientation-horizontal",
                                                        "glyph-orientation-vertical"};

// An element of the text's content and the fragments its character data spans.
struct ElementRange {
  pugi::xml_node node;
  std::size_t style = 0;
  std::size_t first_fragment = 0;
  std::size_t end_fragment = 0;
};

class TextCollector {
 public:
  TextCollector(const ChildStyle& child_style, const TextContext& context, Diagnostics& diagnostics)
      : child_style_(child_style), context_(context), diagnostics_(diagnostics) {}

  std::vector<ComputedStyle> styles;
  std::vector<TextFragment> fragments;
  std::vector<std::size_t> fragment_style;
  std::vector<ElementRange> elements;  // pre-order: descendants after their ancestors

  void collect_element(const pugi::xml_node& node, std::size_t style, int depth) {
    note_unsupported(node);
    const std::size_t index = elements.size();
    elements.push_back({node, style, fragments.size(), fragments.size()});
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
      if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
        Result<std::u32string> decoded = decode_utf8(child.value());
        if (!decoded) {
          diagnostics_.warnings.push_back("<text> character data skipped: " + decoded.error().message);
          continue;
        }
        fragments.push_back({std::move(decoded).value(), styles[style].preserve_spaces});
        fragment_style.push_back(style);
        continue;
      }
      if (child.type() != pugi::node_element) continue;
      const std::string_view name = local_name_of(child);
      if (name == "tspan" || name == "a") {
        if (depth >= context_.max_depth) {
          diagnostics_.warnings.push_back("<" + std::string(name) + "> nested more than " +
                                          std::to_string(context_.max_depth) + " deep; its text is skipped");
          continue;
        }
        ComputedStyle child_style = child_style_(child, styles[style]);
        if (!child_style.display) continue;
        styles.push_back(std::move(child_style));
        collect_element(child, styles.size() - 1, depth + 1);
      } else if (name == "textPath" || name == "tref" || name == "altGlyph") {
        note("<" + std::string(name) + "> is not supported; its text is not drawn");
      }
    }
    elements[index].end_fragment = fragments.size();
  }

 private:
  // An unsupported text feature is a warning, once per kind (no silent loss; docs/svg.md).
  void note(const std::string& message) {
    if (noted_.insert(message).second) diagnostics_.warnings.push_back(message);
  }

  void note_unsupported(const pugi::xml_node& node) {
    const auto check = [&](std::string_view name) {
      if (std::find(kUnsupported.begin(), kUnsupported.end(), name) != kUnsupported.end()) {
        note("<text>: '" + std::string(name) + "' is not supported; ignored");
      }
    };
    for (const pugi::xml_attribute& attribute : node.attributes()) check(attribute.name());
    if (const pugi::xml_attribute css = node.attribute("style")) {
      for (const css::Declaration& declaration : css::parse_declaration_list(css.value()))
        check(declaration.name);
    }
  }

  const ChildStyle& child_style_;
  const TextContext& context_;
  Diagnostics& diagnostics_;
  std::set<std::string> noted_;
};

// An x, y, dx or dy list (SVG 1.1 10.4: <coordinate>s or <length>s separated by comma-wsp). nullopt
// with a warning when any entry is malformed (the attribute is then ignored).
std::optional<std::vector<double>> length_list(const pugi::xml_node& node, const char* attribute,
                                               double percent_reference, double font_size,
                                               const TextContext& context, Diagnostics& diagnostics) {
  std::string_view rest = trim_whitespace(node.attribute(attribute).value());
  std::vector<double> values;
  while (!rest.empty()) {
    std::size_t end = 0;
    while (end < rest.size() && rest[end] != ',' && !is_svg_whitespace(rest[end])) ++end;
    const Result<Length> length = parse_length(rest.substr(0, end));
    if (!length) {
      diagnostics.warnings.push_back("<" + std::string(local_name_of(node)) + "> ignoring " + attribute +
                                     ": " + length.error().message);
      return std::nullopt;
    }
    values.push_back(length_to_pixels(*length, LengthContext{context.dpi, font_size, percent_reference}));
    rest.remove_prefix(end);
    skip_comma_whitespace(rest);
  }
  return values;
}

// A run of characters shaped together.
struct Run {
  std::size_t style = 0;
  std::size_t begin = 0, end = 0;  // characters
  std::size_t chunk = 0;
  Point start;  // pen position before anchoring
  double advance = 0.0;
  const Font* font = nullptr;
  std::optional<TextLayout> layout;
};

struct Chunk {
  double anchor_x = 0.0;  // the chunk's initial current text position
  TextAnchor anchor = TextAnchor::kStart;
  double min_x = 0.0, max_x = 0.0;  // extent of its runs' advances
};

std::string code_point_name(char32_t c) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(c));
  return buffer;
}

}  // namespace

std::vector<TextPiece> text_pieces(const pugi::xml_node& text, const ComputedStyle& style,
                                   const ChildStyle& child_style, const TextContext& context,
                                   FontCache& fonts, Diagnostics& diagnostics) {
  TextCollector collector(child_style, context, diagnostics);
  collector.styles.push_back(style);
  collector.collect_element(text, 0, 0);
  apply_xml_space(collector.fragments);

  // Character offsets of the fragments, and the style of every character.
  std::vector<std::size_t> offsets{0};
  for (const TextFragment& fragment : collector.fragments)
    offsets.push_back(offsets.back() + fragment.text.size());
  const std::size_t count = offsets.back();
  if (count == 0) return {};
  if (count > kMaxTextCharacters) {
    diagnostics.warnings.push_back("<text> with " + std::to_string(count) +
                                   " characters, more than the limit of " +
                                   std::to_string(kMaxTextCharacters) + " (text_layout.h), is not drawn");
    return {};
  }
  std::u32string characters;
  characters.reserve(count);
  std::vector<std::size_t> character_style(count);
  for (std::size_t f = 0; f < collector.fragments.size(); ++f) {
    characters += collector.fragments[f].text;
    std::fill(character_style.begin() + static_cast<std::ptrdiff_t>(offsets[f]),
              character_style.begin() + static_cast<std::ptrdiff_t>(offsets[f + 1]),
              collector.fragment_style[f]);
  }

  // Positions (SVG 1.1 10.5): ancestors first, so that descendants' values win for their characters.
  std::vector<std::optional<double>> abs_x(count), abs_y(count), rel_x(count), rel_y(count);
  for (const ElementRange& element : collector.elements) {
    const std::size_t begin = offsets[element.first_fragment], end = offsets[element.end_fragment];
    const double font_size = collector.styles[element.style].font_size;
    const auto assign = [&](const char* name, double reference, std::vector<std::optional<double>>& target) {
      if (!element.node.attribute(name)) return;
      const std::optional<std::vector<double>> values =
          length_list(element.node, name, reference, font_size, context, diagnostics);
      if (!values) return;
      for (std::size_t k = 0; k < values->size() && begin + k < end; ++k) target[begin + k] = (*values)[k];
    };
    assign("x", context.viewport_width, abs_x);
    assign("y", context.viewport_height, abs_y);
    assign("dx", context.viewport_width, rel_x);
    assign("dy", context.viewport_height, rel_y);
  }

  // Runs and chunks.
  std::vector<Run> runs;
  std::vector<Chunk> chunks;
  std::set<std::pair<const Font*, char32_t>> warned_missing;
  Point pen{0.0, 0.0};
  const auto finish_run = [&](Run& run) {
    run.end = std::max(run.end, run.begin);
    const ComputedStyle& run_style = collector.styles[run.style];
    FontFallback* fallback = fonts.fallback_for(run_style, diagnostics);
    run.font = fallback != nullptr ? &fallback->primary() : nullptr;
    if (fallback != nullptr && run_style.font_size > 0.0) {
      TextStyle text_style;
      text_style.size = run_style.font_size;
      Result<TextLayout> layout =
          layout_text(*fallback, std::u32string_view(characters).substr(run.begin, run.end - run.begin),
                      {0.0, 0.0}, text_style);
      if (!layout) {
        diagnostics.warnings.push_back("<text> run not drawn: " + layout.error().message);
      } else {
        for (char32_t missing : layout->missing_characters) {
          if (warned_missing.emplace(run.font, missing).second) {
            diagnostics.warnings.push_back("'" + run.font->family_name() + "' has no glyph for " +
                                           code_point_name(missing) + "; drawn as the font's .notdef glyph");
          }
        }
        run.advance = layout->lines.empty() ? 0.0 : layout->lines.front().advance;
        run.layout = std::move(layout).value();
      }
    }
    Chunk& chunk = chunks[run.chunk];
    chunk.min_x = std::min({chunk.min_x, run.start.x, run.start.x + run.advance});
    chunk.max_x = std::max({chunk.max_x, run.start.x, run.start.x + run.advance});
    pen = run.start + Vec2{run.advance, 0.0};
  };
  for (std::size_t i = 0; i < count; ++i) {
    const bool absolute = i == 0 || abs_x[i] || abs_y[i];
    const bool shifted = rel_x[i] || rel_y[i];
    if (!absolute && !shifted && character_style[i] == runs.back().style) continue;
    if (!runs.empty()) {
      runs.back().end = i;
      finish_run(runs.back());
    }
    if (absolute) {
      if (abs_x[i]) pen.x = *abs_x[i];
      if (abs_y[i]) pen.y = *abs_y[i];
      chunks.push_back({pen.x, collector.styles[character_style[i]].text_anchor, pen.x, pen.x});
    }
    pen += Vec2{rel_x[i].value_or(0.0), rel_y[i].value_or(0.0)};
    runs.push_back({character_style[i], i, i, chunks.size() - 1, pen, 0.0, nullptr, std::nullopt});
  }
  runs.back().end = count;
  finish_run(runs.back());

  // Anchoring and outlines; consecutive runs of one style share a piece.
  std::vector<TextPiece> pieces;
  std::optional<PathBuilder> builder;
  std::size_t builder_style = 0;
  const auto flush = [&] {
    if (!builder) return;
    Result<Path> path = builder->build();
    builder.reset();
    if (!path) {
      diagnostics.warnings.push_back("<text> outlines not drawn: " + path.error().message);
      return;
    }
    if (path->empty()) return;
    ComputedStyle piece_style = collector.styles[builder_style];
    piece_style.fill_rule = FillRule::kNonZero;
    pieces.push_back({std::move(path).value(), std::move(piece_style)});
  };
  for (Run& run : runs) {
    if (!run.layout) continue;
    const Chunk& chunk = chunks[run.chunk];
    const double shift = chunk.anchor == TextAnchor::kStart ? 0.0
                         : chunk.anchor == TextAnchor::kMiddle
                             ? chunk.anchor_x - 0.5 * (chunk.min_x + chunk.max_x)
                             : chunk.anchor_x - chunk.max_x;
    const Vec2 offset = run.start.to_vec() + Vec2{shift, 0.0};
    for (PositionedGlyph& glyph : run.layout->glyphs) glyph.origin += offset;
    if (builder && builder_style != run.style) flush();
    if (!builder) {
      builder.emplace();
      builder_style = run.style;
    }
    const Status appended = append_text_outlines(*run.font, *run.layout, *builder);
    if (!appended) diagnostics.warnings.push_back("<text> glyphs not drawn: " + appended.error().message);
  }
  flush();
  return pieces;
}

}  // namespace curvescan::svg::detail
