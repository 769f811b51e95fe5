// Characters and their positions (text_layout_job.h): the character data of the element in one string,
// the innermost element of each character, and the per-character x, y, dx, dy and rotate of SVG 1.1 10.5
// (descendants' values winning over their ancestors'), with the accumulated baseline-shift of every element.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/svg/number.h"
#include "text_layout_job.h"

namespace curvescan::svg::detail {

// A list of numbers or lengths (x, y, dx, dy: SVG 1.1 10.4; rotate: numbers) separated by comma-wsp.
// nullopt with a warning when any entry is malformed (the attribute is then ignored).
std::optional<std::vector<double>> length_list(const pugi::xml_node& node, const char* attribute,
                                               LengthAxis axis, double font_size, Diagnostics& diagnostics) {
  std::string_view rest = trim_whitespace(node.attribute(attribute).value());
  std::vector<double> values;
  while (!rest.empty()) {
    std::size_t end = 0;
    while (end < rest.size() && rest[end] != ',' && !is_svg_whitespace(rest[end])) ++end;
    const Result<Length> length = parse_length(rest.substr(0, end));
    // rotate is a list of numbers (SVG 1.1 10.5, <list-of-numbers>): a unit makes the list invalid.
    const bool unit_refused = length && std::string_view(attribute) == "rotate" && length->unit != LengthUnit::kNone;
    if (!length || !std::isfinite(length->value) || unit_refused) {
      diagnostics.warnings.push_back("<" + std::string(local_name_of(node)) + "> ignoring " + attribute + ": " +
                                     (unit_refused ? "angles are plain numbers of degrees, without a unit"
                                      : length     ? "not a finite number"
                                                   : length.error().message));
      return std::nullopt;
    }
    values.push_back(length_to_pixels(*length, LengthContext{axis.dpi, font_size, axis.percent_reference}));
    rest.remove_prefix(end);
    skip_comma_whitespace(rest);
  }
  return values;
}

void TextLayoutJob::gather_characters() {
  offsets_.assign(1, 0);
  for (const TextFragment& fragment : c_.fragments)
    offsets_.push_back(offsets_.back() + fragment.text.size());
  const std::size_t count = offsets_.back();
  characters_.reserve(count);
  character_element_.resize(count);
  middle_.assign(count, false);
  for (std::size_t f = 0; f < c_.fragments.size(); ++f) {
    characters_ += c_.fragments[f].text;
    const std::vector<bool>& middle = c_.fragments[f].middle;
    for (std::size_t i = 0; i < middle.size() && i < c_.fragments[f].text.size(); ++i)
      middle_[offsets_[f] + i] = middle[i];
    std::fill(character_element_.begin() + static_cast<std::ptrdiff_t>(offsets_[f]),
              character_element_.begin() + static_cast<std::ptrdiff_t>(offsets_[f + 1]),
              c_.fragment_element[f]);
  }
  element_begin_.resize(c_.elements.size());
  element_end_.resize(c_.elements.size());
  baseline_shift_.assign(c_.elements.size(), 0.0);
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    element_begin_[e] = offsets_[c_.elements[e].first_fragment];
    element_end_[e] = offsets_[c_.elements[e].end_fragment];
    // baseline-shift (SVG 1.1 10.9.3): relative to the parent's (shifted) baseline; sub and super from
    // the element's font (OS/2 sub/superscript offsets), a percentage of the font size. y down. It
    // applies to tspan, tref, altGlyph and textPath, not to <text> itself (SVG 1.1 10.9.3 "Applies to";
    // CSS Inline 3 4.1: it shifts an inline box within its line, and <text> is the block), as browsers.
    const ElementRange& element = c_.elements[e];
    const BaselineShift& shift = c_.styles[element.style].text.baseline_shift;
    double own = 0.0;
    if (element.parent == kNoElement) {
      own = 0.0;
    } else if (shift.kind == BaselineShift::Kind::kLength) {
      own = -resolve(shift.length, element.style, /*across=*/false);
    } else if (shift.kind != BaselineShift::Kind::kBaseline) {
      if (FontFallback* fonts = fallback_for(element.style)) {
        const FontMetrics m = fonts->primary().metrics();
        const double scale = c_.styles[element.style].font_size / m.units_per_em;
        own = shift.kind == BaselineShift::Kind::kSub ? m.subscript_offset * scale
                                                      : -m.superscript_offset * scale;
      }
    }
    baseline_shift_[e] = (element.parent == kNoElement ? 0.0 : baseline_shift_[element.parent]) + own;
  }
}

void TextLayoutJob::gather_positions() {
  const std::size_t count = characters_.size();
  abs_x_.assign(count, std::nullopt);
  abs_y_.assign(count, std::nullopt);
  rel_x_.assign(count, std::nullopt);
  rel_y_.assign(count, std::nullopt);
  rotate_.assign(count, std::nullopt);
  // Ancestors first, so that descendants' values win for their characters (SVG 1.1 10.5).
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    const ElementRange& element = c_.elements[e];
    const std::size_t begin = element_begin_[e], end = element_end_[e];
    const double font_size = c_.styles[element.style].font_size;
    const auto list = [&](const char* name, LengthAxis axis) -> std::optional<std::vector<double>> {
      if (!element.node.attribute(name)) return std::nullopt;
      return length_list(element.node, name, axis, font_size, diagnostics_);
    };
    const auto assign = [&](const char* name, LengthAxis axis, std::vector<std::optional<double>>& target) {
      if (element.text_path && (name[0] == 'x' || name[0] == 'y')) return;  // textPath has no x and y
      const std::optional<std::vector<double>> values = list(name, axis);
      if (!values) return;
      // The k-th value goes to the k-th addressable character: those text-transform added (middle_) take
      // none (SVG 2 11.8.3 counts addressable characters before text-transform).
      for (std::size_t i = begin, k = 0; i < end && k < values->size(); ++i) {
        if (!middle_[i]) target[i] = (*values)[k++];
      }
    };
    assign("x", context_.horizontal(), abs_x_);
    assign("y", context_.vertical(), abs_y_);
    assign("dx", context_.horizontal(), rel_x_);
    assign("dy", context_.vertical(), rel_y_);
    // rotate (SVG 1.1 10.5): numbers in degrees; the last one applies to every later character of the
    // element that has none of its own from a descendant. Units are refused, so no axis applies.
    if (const std::optional<std::vector<double>> angles = list("rotate", LengthAxis{});
        angles && !angles->empty()) {
      for (std::size_t i = begin, k = 0; i < end; ++i) {
        if (!middle_[i]) rotate_[i] = (*angles)[std::min(k++, angles->size() - 1)];
      }
    }
  }
  // A character text-transform added turns with the one it came from (its typographic character).
  for (std::size_t i = 1; i < count; ++i) {
    if (middle_[i]) rotate_[i] = rotate_[i - 1];
  }
}

}  // namespace curvescan::svg::detail
