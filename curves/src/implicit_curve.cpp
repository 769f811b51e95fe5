// Contouring implicit curves with an interval quadtree (implicit_curve.h): subdivision and certification,
// crossings on a fixed dyadic grid, marching-squares segments, stars at singular points, then polylines.
#include "curvescan/curves/implicit_curve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>

#include "euler_trails.h"

namespace curvescan {
namespace {

// Cell corners and crossings live on a grid of 2^48 steps across the box: deep enough below the deepest
// cell (level 40) that the bisection of a crossing ends far below the tolerance, and exact in doubles.
constexpr int kGridBits = 48;
constexpr int kDeepestLevel = 40;
constexpr int kDeepestToleranceLevel = 36;
constexpr std::uint64_t kGridSize = std::uint64_t{1} << kGridBits;
constexpr int kCrossingLevels = 12;

enum class CellKind : unsigned char { kCertified, kSingular, kUncertified };

struct Leaf {
  std::uint64_t i, j;  // lower-left corner on the grid
  int level;
  CellKind kind;
  bool gradient_may_vanish = false;  // both components of the gradient enclosure contain 0
};

struct GridPoint {
  std::uint64_t i, j;
  bool operator==(const GridPoint&) const = default;
};
struct GridPointHash {
  std::size_t operator()(const GridPoint& p) const noexcept {
    return std::hash<std::uint64_t>()(p.i * 0x9E3779B97F4A7C15ULL ^ (p.j + 0x632BE59BD9B4E019ULL));
  }
};

bool excludes_zero(const Interval& v) {
  return !v.empty && !v.partial && (v.lo > 0 || v.hi < 0);
}
// No change between "f >= 0" and "f < 0" over the interval.
bool no_sign_change(const Interval& v) {
  return !v.empty && !v.partial && (v.lo >= 0 || v.hi < 0);
}
bool positive(double v) {
  return !(v < 0);
}  // NaN counts as >= 0 inside a bisection (deterministically)

// The value of f over the box x × y, from the natural enclosure g.value intersected with the mean value
// form f(c) + ∇f(box) · (p − c) around the centre c (Moore, *Interval Analysis*, ch. 6; Ratschek and
// Rokne, *Computer Methods for the Range of Functions*, 1984). The natural enclosure overestimates by
// O(width) where a variable occurs more than once; the mean value form by O(width²) where the gradient
// is small, which is what decides a cell touching a horizontal or vertical tangent.
Interval value_enclosure(const Expression& f, const Interval& x, const Interval& y,
                         const IntervalGradient& g) {
  if (g.value.empty || g.value.partial || !g.dx.is_bounded() || !g.dy.is_bounded() || g.dx.partial ||
      g.dy.partial) {
    return g.value;
  }
  const double cx = x.lo + (x.hi - x.lo) / 2, cy = y.lo + (y.hi - y.lo) / 2;
  const Interval centre = f.evaluate(Interval::point(cx), Interval::point(cy));
  const Interval form = centre + g.dx * (x - Interval::point(cx)) + g.dy * (y - Interval::point(cy));
  if (form.empty || form.partial || std::isnan(form.lo) || std::isnan(form.hi)) return g.value;
  Interval result = g.value;
  result.lo = std::max(result.lo, form.lo);
  result.hi = std::min(result.hi, form.hi);
  return result;
}

class ImplicitContourer {
 public:
  ImplicitContourer(const Expression& f, Point min, Point max, const ImplicitCurveOptions& options)
      : f_(f), min_(min), extent_(max - min), options_(options) {}

  double world_x(std::uint64_t i) const { return min_.x + extent_.x * (static_cast<double>(i) * 0x1p-48); }
  double world_y(std::uint64_t j) const { return min_.y + extent_.y * (static_cast<double>(j) * 0x1p-48); }
  Point world(GridPoint p) const { return {world_x(p.i), world_y(p.j)}; }

  Status subdivide(int max_level, ImplicitCurve& curve) {
    // Crossings are located to 2^-12 of the deepest cell: far below the tolerance, and a dozen or so
    // bisection steps for a typical leaf rather than forty.
    crossing_step_ = kGridSize >> std::min(kGridBits, max_level + kCrossingLevels);
    const std::size_t terms = std::max<std::size_t>(1, f_.program().size());
    const std::size_t max_cells =
        std::min(options_.max_cells, std::max<std::size_t>(1, options_.max_work / terms));
    struct Cell {
      std::uint64_t i, j;
      int level;
    };
    std::vector<Cell> stack{{0, 0, 0}};
    while (!stack.empty()) {
      const Cell cell = stack.back();
      stack.pop_back();
      if (++curve.cells > max_cells) {
        return Error{ErrorKind::kLimitExceeded,
                     "the curve needs more than " + std::to_string(max_cells) +
                         " quadtree cells at this tolerance" +
                         (max_cells < options_.max_cells ? " (the work limit for an expression of " +
                                                               std::to_string(f_.program().size()) + " terms)"
                                                         : std::string()) +
                         " (raise the tolerance or shrink the box)"};
      }
      const std::uint64_t s = kGridSize >> cell.level;
      const Interval x{world_x(cell.i), world_x(cell.i + s)};
      const Interval y{world_y(cell.j), world_y(cell.j + s)};
      IntervalGradient g = f_.evaluate_gradient(x, y);
      g.value = value_enclosure(f_, x, y, g);
      if (g.value.empty || g.value.lo >= 0 || g.value.hi < 0) continue;  // no sign change in the cell
      const bool small = std::hypot(x.width(), y.width()) <= options_.tolerance;
      if (small && certified(g, x, y)) {
        leaves_.push_back({cell.i, cell.j, cell.level, CellKind::kCertified});
        continue;
      }
      if (cell.level < max_level) {
        const std::uint64_t h = s / 2;
        for (const auto& [di, dj] : {std::pair{h, h}, {0, h}, {h, 0}, {0, 0}}) {
          stack.push_back({cell.i + di, cell.j + dj, cell.level + 1});
        }
        continue;
      }
      // Not certified at the deepest level: grouped with its neighbours (contour_singular) where f is defined
      // on the whole cell.
      leaves_.push_back({cell.i, cell.j, cell.level,
                         g.value.partial ? CellKind::kUncertified : CellKind::kSingular,
                         g.dx.contains_zero() && g.dy.contains_zero()});
    }
    return {};
  }

  // The topology certificate of implicit_curve.h: ∂f/∂y excludes 0 on the cell and each horizontal edge
  // has at most one crossing, or the same with x and y exchanged.
  bool certified(const IntervalGradient& g, const Interval& x, const Interval& y) const {
    if (g.value.partial) return false;
    auto edge_ok = [this](const Interval& ex, const Interval& ey, bool along_x) {
      const IntervalGradient e = f_.evaluate_gradient(ex, ey);
      return no_sign_change(value_enclosure(f_, ex, ey, e)) || excludes_zero(along_x ? e.dx : e.dy);
    };
    if (excludes_zero(g.dy) && edge_ok(x, Interval::point(y.lo), true) &&
        edge_ok(x, Interval::point(y.hi), true)) {
      return true;
    }
    if (excludes_zero(g.dx) && edge_ok(Interval::point(x.lo), y, false) &&
        edge_ok(Interval::point(x.hi), y, false)) {
      return true;
    }
    return false;
  }

  double value_at(GridPoint p) {
    const auto found = corner_values_.find(p);
    if (found != corner_values_.end()) return found->second;
    const Point w = world(p);
    const double v = f_.evaluate(w.x, w.y);
    corner_values_.emplace(p, v);
    return v;
  }

  // The vertex of the crossing on the edge a -> b (a horizontal or vertical, a before b), or none. The
  // bisection halves the edge on the dyadic grid down to one crossing step (the same for every cell), so
  // every cell whose edge contains the crossing ends on the same step and the same vertex.
  std::optional<std::size_t> crossing(GridPoint a, GridPoint b) {
    const double va = value_at(a), vb = value_at(b);
    if (std::isnan(va) || std::isnan(vb) || positive(va) == positive(vb)) return std::nullopt;
    const bool horizontal = a.j == b.j;
    std::uint64_t lo = horizontal ? a.i : a.j;
    std::uint64_t hi = horizontal ? b.i : b.j;
    const bool lo_positive = positive(va);
    double value_lo = va, value_hi = vb;
    while (hi - lo > crossing_step_) {
      const std::uint64_t mid = lo + (hi - lo) / 2;
      const GridPoint m = horizontal ? GridPoint{mid, a.j} : GridPoint{a.i, mid};
      const Point w = world(m);
      const double value = f_.evaluate(w.x, w.y);
      if (positive(value) == lo_positive) {
        lo = mid;
        value_lo = value;
      } else {
        hi = mid;
        value_hi = value;
      }
    }
    const auto key = std::make_tuple(horizontal, horizontal ? a.j : a.i, lo);
    const auto found = crossing_vertices_.find(key);
    if (found != crossing_vertices_.end()) return found->second;
    const Point p0 = horizontal ? world({lo, a.j}) : world({a.i, lo});
    const Point p1 = horizontal ? world({hi, a.j}) : world({a.i, hi});
    // Within the last step, where f is as good as linear, the secant's zero (the middle if a value is NaN).
    const double t = value_lo / (value_lo - value_hi);
    vertices_.push_back(p0 + (p1 - p0) * (t >= 0 && t <= 1 ? t : 0.5));
    crossing_vertices_.emplace(key, vertices_.size() - 1);
    return vertices_.size() - 1;
  }

  // The crossings on the four edges of a cell, in the order bottom, right, top, left (none where absent).
  std::array<std::optional<std::size_t>, 4> crossings(const Leaf& leaf) {
    const std::uint64_t s = kGridSize >> leaf.level;
    const GridPoint c0{leaf.i, leaf.j}, c1{leaf.i + s, leaf.j}, c2{leaf.i + s, leaf.j + s},
        c3{leaf.i, leaf.j + s};
    return {crossing(c0, c1), crossing(c1, c2), crossing(c3, c2), crossing(c0, c3)};
  }

  void add_edge(std::size_t a, std::size_t b) {
    if (a != b) edges_.insert({std::min(a, b), std::max(a, b)});
  }

  // Marching squares: the crossings paired as they cut off the corners; a saddle (four crossings) is
  // decided by the sign at the centre.
  void march(const Leaf& leaf) {
    const auto r = crossings(leaf);
    std::vector<std::size_t> found;
    for (const auto& v : r) {
      if (v) found.push_back(*v);
    }
    if (found.size() == 4) {
      const std::uint64_t s = kGridSize >> leaf.level;
      const Point centre = world({leaf.i + s / 2, leaf.j + s / 2});
      const bool centre_like_c0 =
          positive(f_.evaluate(centre.x, centre.y)) == positive(value_at({leaf.i, leaf.j}));
      if (centre_like_c0) {  // cut off the corners c1 and c3
        add_edge(*r[0], *r[1]);
        add_edge(*r[2], *r[3]);
      } else {  // cut off c0 and c2
        add_edge(*r[0], *r[3]);
        add_edge(*r[1], *r[2]);
      }
      return;
    }
    if (found.size() >= 2) add_edge(found[0], found[1]);
  }

  // Groups of adjacent singular cells (all at the deepest level, so of one size): joined to their centre
  // when the group is within the tolerance, contoured as uncertified cells otherwise.
  void contour_singular(const std::vector<Leaf>& singular, ImplicitCurve& curve) {
    std::unordered_map<GridPoint, std::size_t, GridPointHash> index;
    for (std::size_t k = 0; k < singular.size(); ++k)
      index.emplace(GridPoint{singular[k].i, singular[k].j}, k);
    std::vector<std::size_t> parent(singular.size());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    auto root = [&](std::size_t v) {
      while (parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for (std::size_t k = 0; k < singular.size(); ++k) {
      const std::uint64_t s = kGridSize >> singular[k].level;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const GridPoint n{singular[k].i + static_cast<std::uint64_t>(di) * s,
                            singular[k].j + static_cast<std::uint64_t>(dj) * s};
          const auto found = index.find(n);
          if (found != index.end()) parent[root(k)] = root(found->second);
        }
      }
    }
    std::map<std::size_t, std::vector<std::size_t>> groups;
    for (std::size_t k = 0; k < singular.size(); ++k) groups[root(k)].push_back(k);
    for (const auto& [group_root, members] : groups) {
      Point low{INFINITY, INFINITY}, high{-INFINITY, -INFINITY};
      for (const std::size_t k : members) {
        const std::uint64_t s = kGridSize >> singular[k].level;
        const Point a = world({singular[k].i, singular[k].j}),
                    b = world({singular[k].i + s, singular[k].j + s});
        low = {std::min(low.x, a.x), std::min(low.y, a.y)};
        high = {std::max(high.x, b.x), std::max(high.y, b.y)};
      }
      if (std::hypot(high.x - low.x, high.y - low.y) > options_.tolerance) {
        for (const std::size_t k : members) march(singular[k]);
        curve.uncertified_cells += members.size();
        continue;
      }
      // Spokes to the crossings on the group's outer edges; a crossing between two cells of the group is
      // inside the star already.
      std::vector<std::size_t> spokes;
      for (const std::size_t k : members) {
        const Leaf& cell = singular[k];
        const std::uint64_t s = kGridSize >> cell.level;
        const GridPoint across[4] = {
            {cell.i, cell.j - s}, {cell.i + s, cell.j}, {cell.i, cell.j + s}, {cell.i - s, cell.j}};
        const auto r = crossings(cell);
        for (int e = 0; e < 4; ++e) {
          if (r[e] && !index.contains(across[e])) spokes.push_back(*r[e]);
        }
      }
      if (spokes.empty())
        continue;  // a sign change the corners do not see (an isolated point or a tiny loop)
      const Point centre = low + (high - low) * 0.5;
      vertices_.push_back(centre);
      for (const std::size_t v : spokes) add_edge(v, vertices_.size() - 1);
      // Where the gradient may vanish the branches meet at a singular point; elsewhere the group is a
      // near-tangency joined within the tolerance but not certified.
      const bool may_vanish = std::any_of(members.begin(), members.end(),
                                          [&](std::size_t k) { return singular[k].gradient_may_vanish; });
      if (may_vanish) {
        curve.singular_points.push_back(centre);
      } else {
        curve.uncertified_cells += members.size();
      }
    }
  }

  void contour(ImplicitCurve& curve) {
    std::vector<Leaf> singular;
    for (const Leaf& leaf : leaves_) {
      if (leaf.kind == CellKind::kSingular) {
        singular.push_back(leaf);
        continue;
      }
      if (leaf.kind == CellKind::kUncertified) ++curve.uncertified_cells;
      march(leaf);
    }
    contour_singular(singular, curve);
    const std::vector<std::pair<std::size_t, std::size_t>> edge_list(edges_.begin(), edges_.end());
    for (const std::vector<std::size_t>& trail : detail::euler_trails(vertices_.size(), edge_list)) {
      std::vector<Point>& polyline = curve.polylines.emplace_back();
      polyline.reserve(trail.size());
      for (const std::size_t v : trail) polyline.push_back(vertices_[v]);
    }
  }

 private:
  const Expression& f_;
  Point min_;
  Vec2 extent_;
  const ImplicitCurveOptions& options_;
  std::uint64_t crossing_step_ = 1;
  std::vector<Leaf> leaves_;
  std::unordered_map<GridPoint, double, GridPointHash> corner_values_;
  std::map<std::tuple<bool, std::uint64_t, std::uint64_t>, std::size_t> crossing_vertices_;
  std::vector<Point> vertices_;
  std::set<std::pair<std::size_t, std::size_t>> edges_;
};

}  // namespace

Result<ImplicitCurve> contour_implicit_curve(const Expression& f, Point min, Point max,
                                             const ImplicitCurveOptions& options) {
  const Vec2 extent = max - min;
  if (!std::isfinite(min.x) || !std::isfinite(min.y) || !std::isfinite(max.x) || !std::isfinite(max.y) ||
      !(extent.x > 0) || !(extent.y > 0) || !std::isfinite(extent.x) || !std::isfinite(extent.y)) {
    return Error{
        ErrorKind::kInvalidArgument,
        "the box must be [[xmin, ymin], [xmax, ymax]] with finite numbers, xmin < xmax and ymin < ymax"};
  }
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance) || options.extra_levels < 0) {
    return Error{ErrorKind::kInvalidArgument, "the tolerance must be a positive number"};
  }
  int tolerance_level = 0;
  while (std::hypot(extent.x, extent.y) * std::ldexp(1.0, -tolerance_level) > options.tolerance) {
    if (++tolerance_level > kDeepestToleranceLevel) {
      return Error{ErrorKind::kLimitExceeded,
                   "the tolerance is finer than 2^-36 of the box's diagonal (raise the "
                   "tolerance or shrink the box)"};
    }
  }
  const int max_level = std::min(tolerance_level + options.extra_levels, kDeepestLevel);
  ImplicitContourer contourer(f, min, max, options);
  ImplicitCurve curve;
  CURVESCAN_PROPAGATE(contourer.subdivide(max_level, curve));
  contourer.contour(curve);
  return curve;
}

}  // namespace curvescan
