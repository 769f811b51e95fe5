// SVG path-data parsing (path_data.h): a single pass over the text, one command segment at a time. All
// arguments of a segment are read before anything is appended, so an error inside a segment leaves the
// path exactly as it was after the previous segment -- the SVG error rule.
#include "curvescan/svg/path_data.h"

#include <array>
#include <cmath>
#include <numbers>

#include "curvescan/svg/number.h"

namespace curvescan::svg {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

// Number of numeric arguments of each command (flags of A count as arguments).
int argument_count(char command) noexcept {
  switch (command) {
    case 'M':
    case 'm':
    case 'L':
    case 'l':
    case 'T':
    case 't':
      return 2;
    case 'H':
    case 'h':
    case 'V':
    case 'v':
      return 1;
    case 'C':
    case 'c':
      return 6;
    case 'S':
    case 's':
    case 'Q':
    case 'q':
      return 4;
    case 'A':
    case 'a':
      return 7;
    case 'Z':
    case 'z':
      return 0;
    default:
      return -1;
  }
}

bool starts_number(std::string_view text) noexcept {
  if (text.empty()) return false;
  const char c = text.front();
  return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

bool is_finite(Point p) noexcept {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

class PathDataParser {
 public:
  PathDataParser(std::string_view data, PathBuilder& builder) : data_(data), rest_(data), builder_(builder) {}

  std::optional<PathDataError> run() {
    skip_whitespace(rest_);
    if (rest_.empty()) return std::nullopt;
    if (rest_.front() != 'M' && rest_.front() != 'm')
      return error("path data must start with a moveto (M or m)");
    char command = 0;
    while (true) {
      skip_whitespace(rest_);
      if (rest_.empty()) return std::nullopt;
      const char next = rest_.front();
      if (argument_count(next) >= 0) {
        command = next;
        rest_.remove_prefix(1);
        skip_whitespace(rest_);
      } else if (!starts_number(rest_)) {
        return error(std::string("unexpected character '") + next + "'");
      } else if (command == 'Z' || command == 'z') {
        return error("a number cannot follow closepath (Z)");
      }
      // else: an implicit repeat of `command` (a moveto repeats as a lineto, already substituted below).
      std::array<double, 7> args{};
      const int count = argument_count(command);
      for (int i = 0; i < count; ++i) {
        const bool is_flag = (command == 'A' || command == 'a') && (i == 3 || i == 4);
        if (!(is_flag ? read_flag(args[static_cast<std::size_t>(i)])
                      : read_number(args[static_cast<std::size_t>(i)]))) {
          return error(is_flag ? "expected an arc flag (0 or 1)" : "expected a number");
        }
        skip_comma_whitespace(rest_);
      }
      if (!apply(command, args)) return error("a coordinate overflows");
      if (command == 'M') command = 'L';
      if (command == 'm') command = 'l';
    }
  }

 private:
  std::optional<PathDataError> error(const std::string& what) const {
    const std::size_t offset = data_.size() - rest_.size();
    return PathDataError{offset, "path data: " + what + " at offset " + std::to_string(offset)};
  }

  bool read_number(double& value) {
    const std::optional<double> number = consume_number(rest_);
    if (!number) return false;
    value = *number;
    return true;
  }

  bool read_flag(double& value) {
    if (rest_.empty() || (rest_.front() != '0' && rest_.front() != '1')) return false;
    value = rest_.front() == '1' ? 1.0 : 0.0;
    rest_.remove_prefix(1);
    return true;
  }

  // Appends one command segment; false (nothing appended) when a point would not be finite.
  bool apply(char command, const std::array<double, 7>& a) {
    const bool relative = command >= 'a' && command <= 'z';
    const Vec2 origin = relative ? current_ - Point{0, 0} : Vec2{0, 0};
    auto at = [&](double x, double y) { return Point{x, y} + origin; };
    std::optional<Point> last_cubic_control, last_quad_control;
    switch (command) {
      case 'M':
      case 'm': {
        const Point p = at(a[0], a[1]);
        if (!is_finite(p)) return false;
        builder_.move_to(p);
        current_ = subpath_start_ = p;
        break;
      }
      case 'L':
      case 'l':
      case 'H':
      case 'h':
      case 'V':
      case 'v': {
        Point p = at(a[0], a[1]);
        if (command == 'H' || command == 'h') p = {relative ? current_.x + a[0] : a[0], current_.y};
        if (command == 'V' || command == 'v') p = {current_.x, relative ? current_.y + a[0] : a[0]};
        if (!is_finite(p)) return false;
        builder_.line_to(p);
        current_ = p;
        break;
      }
      case 'C':
      case 'c':
      case 'S':
      case 's': {
        const bool smooth = command == 'S' || command == 's';
        const Point c1 = smooth ? reflected(previous_cubic_control_) : at(a[0], a[1]);
        const int k = smooth ? 0 : 2;  // index of the second control point's x
        const Point c2 = at(a[static_cast<std::size_t>(k)], a[static_cast<std::size_t>(k + 1)]);
        const Point p = at(a[static_cast<std::size_t>(k + 2)], a[static_cast<std::size_t>(k + 3)]);
        if (!is_finite(c1) || !is_finite(c2) || !is_finite(p)) return false;
        builder_.cubic_to(c1, c2, p);
        current_ = p;
        last_cubic_control = c2;
        break;
      }
      case 'Q':
      case 'q':
      case 'T':
      case 't': {
        const bool smooth = command == 'T' || command == 't';
        const Point c = smooth ? reflected(previous_quad_control_) : at(a[0], a[1]);
        const Point p = smooth ? at(a[0], a[1]) : at(a[2], a[3]);
        if (!is_finite(c) || !is_finite(p)) return false;
        builder_.quad_to(c, p);
        current_ = p;
        last_quad_control = c;
        break;
      }
      case 'A':
      case 'a': {
        const Point p = at(a[5], a[6]);
        if (!is_finite(p)) return false;
        builder_.svg_arc_to(a[0], a[1], a[2] * kRadiansPerDegree, a[3] != 0.0, a[4] != 0.0, p);
        current_ = p;
        break;
      }
      default:  // 'Z', 'z'
        // "M x y Z" is a zero-length closed subpath, which a round or square cap still strokes as a dot
        // (SVG 1.1 11.4, "stroke-linecap"); PathBuilder drops a contour with no drawing verb, so the
        // closing segment is made explicit.
        if (!drawn_since_move_) builder_.line_to(subpath_start_);
        builder_.close();
        current_ = subpath_start_;
        break;
    }
    previous_cubic_control_ = last_cubic_control;
    previous_quad_control_ = last_quad_control;
    drawn_since_move_ = command != 'M' && command != 'm' && command != 'Z' && command != 'z';
    return true;
  }

  // The reflection of the previous segment's last control point about the current point (SVG 1.1
  // 8.3.6: "the reflection of the second control point on the previous command relative to the current
  // point"), or the current point itself when the previous segment was of another kind.
  Point reflected(std::optional<Point> control) const noexcept {
    if (!control) return current_;
    return current_ + (current_ - *control);
  }

  std::string_view data_;
  std::string_view rest_;
  PathBuilder& builder_;
  Point current_{0, 0};
  Point subpath_start_{0, 0};
  std::optional<Point> previous_cubic_control_;
  std::optional<Point> previous_quad_control_;
  bool drawn_since_move_ = false;  // a drawing command since the last moveto or closepath
};

}  // namespace

std::optional<PathDataError> append_path_data(std::string_view data, PathBuilder& builder) {
  return PathDataParser(data, builder).run();
}

}  // namespace curvescan::svg
