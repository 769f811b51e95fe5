// viewBox, preserveAspectRatio and their transform (viewport.h), SVG 1.1 sections 7.7-7.8.
#include "curvescan/svg/viewport.h"

#include <algorithm>
#include <string>

#include "curvescan/svg/number.h"

namespace curvescan::svg {

Result<ViewBox> parse_view_box(std::string_view text) {
  const NumberList list = parse_number_list(text);
  if (!list.complete || list.values.size() != 4) {
    return Error{ErrorKind::kInvalidArgument, "viewBox '" + std::string(text) + "' is not four numbers"};
  }
  const ViewBox box{list.values[0], list.values[1], list.values[2], list.values[3]};
  if (box.width < 0.0 || box.height < 0.0) {
    return Error{ErrorKind::kInvalidArgument, "viewBox '" + std::string(text) + "' has a negative size"};
  }
  return box;
}

Result<PreserveAspectRatio> parse_preserve_aspect_ratio(std::string_view text) {
  const auto bad = [&] {
    return Error{ErrorKind::kInvalidArgument, "preserveAspectRatio '" + std::string(text) + "' is not valid"};
  };
  std::string_view rest = trim_whitespace(text);
  const auto next_word = [&]() {
    skip_whitespace(rest);
    std::size_t end = 0;
    while (end < rest.size() && !is_svg_whitespace(rest[end])) ++end;
    const std::string_view word = rest.substr(0, end);
    rest.remove_prefix(end);
    return word;
  };
  std::string_view word = next_word();
  if (word == "defer") word = next_word();  // only meaningful on <image>; ignored elsewhere (7.8)
  PreserveAspectRatio aspect;
  if (word == "none") {
    aspect.none = true;
  } else if (word.size() == 8 && word.substr(0, 1) == "x" && word.substr(4, 1) == "Y") {
    const auto fraction = [](std::string_view name) {
      return name == "Min" ? 0.0 : name == "Mid" ? 0.5 : name == "Max" ? 1.0 : -1.0;
    };
    aspect.align_x = fraction(word.substr(1, 3));
    aspect.align_y = fraction(word.substr(5, 3));
    if (aspect.align_x < 0.0 || aspect.align_y < 0.0) return bad();
  } else {
    return bad();
  }
  const std::string_view mode = next_word();
  if (mode == "slice") {
    aspect.slice = true;
  } else if (!mode.empty() && mode != "meet") {
    return bad();
  }
  if (!next_word().empty()) return bad();
  return aspect;
}

Affine view_box_transform(const ViewBox& view_box, const PreserveAspectRatio& aspect, double x, double y,
                          double width, double height) noexcept {
  double scale_x = width / view_box.width;
  double scale_y = height / view_box.height;
  if (aspect.none) {
    return Affine::translate(x, y) * Affine::scale(scale_x, scale_y) *
           Affine::translate(-view_box.x, -view_box.y);
  }
  const double scale = aspect.slice ? std::max(scale_x, scale_y) : std::min(scale_x, scale_y);
  // The leftover space (negative for slice) is distributed by the alignment fraction.
  const double tx = x + (width - view_box.width * scale) * aspect.align_x;
  const double ty = y + (height - view_box.height * scale) * aspect.align_y;
  return Affine::translate(tx, ty) * Affine::scale(scale) * Affine::translate(-view_box.x, -view_box.y);
}

}  // namespace curvescan::svg
