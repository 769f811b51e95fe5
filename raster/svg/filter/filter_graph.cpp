// Running a filter's primitives and the CSS filter functions (filter_graph.h).
#include "filter_graph.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>

#include "color_matrix.h"
#include "component_transfer.h"
#include "drop_shadow.h"
#include "gaussian_blur.h"
#include "offset.h"
#include "xml_names.h"

namespace curvescan::svg::detail::filter {
namespace {

// Zeroes what `stale` (memory given back by an earlier result) holds outside `image`'s extent, which the
// primitive has just written whole.
void clear_stale(FilterImage& image, PixelRect stale) {
  const PixelRect keep = image.extent;
  image.extent = stale.unite(keep);
  clear_outside(image, keep);
}

// One image a primitive can read: a standard input or a primitive's result.
struct FilterResult {
  FilterImage owned;
  const FilterImage* borrowed = nullptr;  // SourceGraphic used as it is, without a copy
  ColorSpace space = ColorSpace::kSrgb;
  PixelRect subregion;
  Rect user_subregion;
  bool standard = false;   // a standard input (its subregion is the filter region, section 9.7)
  bool colorless = false;  // every colour channel is 0 (SourceAlpha and what moves or blurs it): the same
                           // image in both colour spaces, so it is never converted
  std::unique_ptr<FilterImage> converted;  // the image in the other colour space, made on first use
  // SourceAlpha not made yet: the alpha of this image inside `alpha_ink`. A blur reads it there directly
  // (PrimitiveCall::in_alpha_only); any other primitive has it made first (FilterRun::make_alpha).
  const FilterImage* alpha_of = nullptr;
  PixelRect alpha_ink;
  // feFlood not drawn yet: this premultiplied colour (in `space`) inside `constant_area`, transparent
  // elsewhere. feComposite reads it as a colour (PrimitiveCall::in_constant) where it covers what it
  // computes; anything else has it drawn first (FilterRun::make_constant).
  std::optional<std::array<float, 4>> constant;
  PixelRect constant_area;

  const FilterImage& image() const { return borrowed != nullptr ? *borrowed : owned; }

  /// The image in `wanted` (no copy when it is the image itself).
  [[nodiscard]] bool is_in_space(ColorSpace wanted) const { return wanted == space || colorless; }

  /// The image in `wanted`; `spare` gives the memory of a conversion (FilterRun::acquire), not cleared:
  /// the conversion writes the whole extent and clears the rest of what `spare` says is stale.
  template <class Spare>
  const FilterImage& in_space(ColorSpace wanted, Spare&& spare) {
    if (is_in_space(wanted)) return image();
    if (!converted) {
      PixelRect stale;
      converted = std::make_unique<FilterImage>(spare(&stale));
      convert_color_space(image(), space, wanted, *converted);
      clear_stale(*converted, stale);
    }
    return *converted;
  }
};

Rect union_of(const Rect& a, const Rect& b) {
  return Rect{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

class FilterRun {
 public:
  FilterRun(const FilterDefinition& definition, const FilterSpace& space, PixelRect region,
            const FilterSources& sources, const FilterEnvironment& environment, Diagnostics& diagnostics)
      : definition_(definition),
        space_(space),
        region_(region),
        sources_(sources),
        environment_(environment),
        diagnostics_(diagnostics) {}

  // The result; in sRGB unless `space` is given, which then receives the space it is in (the caller
  // converts while quantizing, to_image).
  FilterImage run(ColorSpace* space = nullptr) {
    if (space != nullptr) *space = ColorSpace::kSrgb;
    const auto transparent = [this] {
      FilterImage image(sources_.source_graphic->width, sources_.source_graphic->height);
      image.extent = PixelRect{};
      return image;
    };
    // The plan, made when the filter was resolved (resolved_filter.h): each primitive's inputs resolved to
    // the primitive that makes them (or a standard input), and the last primitive that reads each result,
    // so that an image nobody reads any more is given back for reuse (a drop shadow then holds three or
    // four images at a time, not one per step).
    const ResolvedFilter& plan = *definition_.filter;
    if (!plan.unsupported.empty()) return transparent();
    for (const auto& [name, index] : plan.standard_last_use) standard_last_use_[name] = index;
    // A filter without primitives leaves nothing to draw (Filter Effects 1, section 8: transparent black).
    if (plan.primitives.empty()) return transparent();
    // What each result must hold: the last, what the caller needs; an earlier one, what the primitives
    // reading it need of it to make what they must (input_needed), carried back from the last.
    const PixelRect everything{-(1 << 30), -(1 << 30), 1 << 30, 1 << 30};
    std::vector<PixelRect> needed(plan.primitives.size());
    needed.back() = sources_.needed;
    for (std::size_t i = plan.primitives.size(); i-- > 0;) {
      for (const PrimitiveInput& input : plan.primitives[i].inputs) {
        if (input.producer < 0) continue;
        PixelRect& wanted = needed[static_cast<std::size_t>(input.producer)];
        wanted = wanted.unite(input_needed(plan.primitives[i], space_, needed[i], everything));
      }
    }
    for (std::size_t i = 0; i < plan.primitives.size(); ++i) {
      std::vector<FilterResult*> inputs;
      for (const PrimitiveInput& input : plan.primitives[i].inputs) {
        inputs.push_back(input.producer >= 0 ? results_[static_cast<std::size_t>(input.producer)].get()
                                             : standard_input(input.standard));
      }
      // Inputs read for the last time here, once: their memory may hold this result
      // (PrimitiveEntry::in_place).
      std::vector<bool> last_read;
      for (const PrimitiveInput& input : plan.primitives[i].inputs) {
        const bool once =
            std::count_if(plan.primitives[i].inputs.begin(), plan.primitives[i].inputs.end(),
                          [&](const PrimitiveInput& other) { return other.producer == input.producer; }) == 1;
        last_read.push_back(input.producer >= 0 && once &&
                            plan.primitives[static_cast<std::size_t>(input.producer)].last_use ==
                                static_cast<int>(i));
      }
      std::optional<FilterResult> result = run_primitive(plan.primitives[i], inputs, last_read, needed[i]);
      if (!result) return transparent();
      results_.push_back(std::make_unique<FilterResult>(std::move(*result)));
      // A result nobody reads (and that is not the filter's result) is given back at once.
      if (plan.primitives[i].last_use < 0 && i + 1 < plan.primitives.size()) release(*results_.back());
      for (const PrimitiveInput& input : plan.primitives[i].inputs) {
        if (input.producer < 0) {
          const auto found = standard_.find(input.standard);
          if (found != standard_.end() && standard_last_use_[input.standard] == static_cast<int>(i))
            release(*found->second);
          continue;
        }
        const auto producer = static_cast<std::size_t>(input.producer);
        if (plan.primitives[producer].last_use == static_cast<int>(i) && results_[producer])
          release(*results_[producer]);
      }
    }
    FilterResult& last = *results_.back();
    if (last.constant) make_constant(last);
    if (last.space == ColorSpace::kSrgb || last.colorless) return std::move(last.owned);
    if (space != nullptr) {
      *space = last.space;
      return std::move(last.owned);
    }
    convert_color_space(last.owned, last.space, ColorSpace::kSrgb);
    return std::move(last.owned);
  }

 private:
  // A transparent image of the filter image's size (its extent empty), in memory given back by an earlier
  // result if any: only that result's extent needs clearing, since outside it the memory is zero. With
  // `stale`, nothing is cleared and *stale is where old values may remain: the caller writes its extent
  // whole, then calls clear_stale.
  FilterImage acquire(PixelRect* stale = nullptr) {
    const FilterImage& source = *sources_.source_graphic;
    FilterImage image;
    if (stale != nullptr) *stale = PixelRect{};
    if (spare_.empty()) {
      image = FilterImage(source.width, source.height);
    } else {
      image.width = source.width;
      image.height = source.height;
      image.rgba = std::move(spare_.back().pixels);
      image.extent = spare_.back().dirty;
      spare_.pop_back();
      if (stale != nullptr) {
        *stale = image.extent;
      } else {
        clear_outside(image, PixelRect{});
      }
    }
    image.extent = PixelRect{};
    return image;
  }

  // Gives the memory of a result nobody reads any more back for reuse.
  void release(FilterResult& result) {
    const std::size_t size = sources_.source_graphic->rgba.size();
    if (result.owned.rgba.size() == size)
      spare_.push_back({std::move(result.owned.rgba), result.owned.extent});
    if (result.converted && result.converted->rgba.size() == size)
      spare_.push_back({std::move(result.converted->rgba), result.converted->extent});
    result.owned = FilterImage();
    result.converted.reset();
  }

  // An feFlood drawn (FilterResult::constant).
  void make_constant(FilterResult& result) {
    PixelRect stale;
    result.owned = acquire(&stale);
    const std::array<float, 4>& value = *result.constant;
    const PixelRect area = result.constant_area.intersect(result.owned.bounds());
    for (int y = area.y0; y < area.y1; ++y) {
      for (int x = area.x0; x < area.x1; ++x) std::copy(value.begin(), value.end(), result.owned.pixel(x, y));
    }
    result.owned.extent = area;
    clear_stale(result.owned, stale);
    result.constant.reset();
  }

  // SourceAlpha as an image of its own (FilterResult::alpha_of).
  void make_alpha(FilterResult& result) {
    const FilterImage& source = *result.alpha_of;
    const PixelRect ink = result.alpha_ink;
    result.owned = acquire();
    for (int y = ink.y0; y < ink.y1; ++y) {
      const float* from = source.pixel(ink.x0, y);
      float* to = result.owned.pixel(ink.x0, y);
      for (int i = 0; i < ink.width(); ++i) to[4 * i + 3] = from[4 * i + 3];
    }
    result.owned.extent = ink;
    result.alpha_of = nullptr;
  }

  FilterResult* standard_input(std::string_view name) {
    const std::string key(name);
    if (const auto found = standard_.find(key); found != standard_.end()) return found->second.get();
    auto result = std::make_unique<FilterResult>();
    result->standard = true;
    result->space = ColorSpace::kSrgb;
    result->subregion = region_;
    result->user_subregion = definition_.region;
    const FilterImage& source = *sources_.source_graphic;
    // The source's ink inside the filter region: all the standard inputs drawn from it hold.
    const PixelRect ink = source.extent.intersect(region_).intersect(source.bounds());
    if (name == "SourceGraphic" && region_.intersect(source.bounds()) == source.bounds()) {
      result->borrowed = &source;
    } else if (name == "SourceGraphic") {
      result->owned = acquire();
      for (int y = ink.y0; y < ink.y1; ++y)
        std::copy(source.pixel(ink.x0, y), source.pixel(ink.x1, y), result->owned.pixel(ink.x0, y));
      result->owned.extent = ink;
    } else {  // SourceAlpha, the only other standard input (resolved_filter.cpp)
      result->colorless = true;
      result->alpha_of = &source;
      result->alpha_ink = ink;
    }
    FilterResult* pointer = result.get();
    standard_.emplace(key, std::move(result));
    return pointer;
  }

  // x, y, width, height of `primitive` in user space (section 9.7), given the default (union or filter
  // region). In bounding-box units a given value is a fraction of the box; missing values keep the default.
  Rect subregion_of(const ResolvedPrimitive& primitive, const Rect& fallback) const {
    const bool box = definition_.bounding_box_primitives;
    const auto coordinate = [&](double value, double fallback_user, bool is_x, bool is_size) {
      if (std::isnan(value)) return fallback_user;
      if (!box) return value;
      if (is_size) return is_x ? space_.user_width(value) : space_.user_height(value);
      return is_x ? space_.user_x(value) : space_.user_y(value);
    };
    const std::array<double, 4>& given = primitive.subregion;
    const double x = coordinate(given[0], fallback.x0, true, false);
    const double y = coordinate(given[1], fallback.y0, false, false);
    const double w = coordinate(given[2], fallback.width(), true, true);
    const double h = coordinate(given[3], fallback.height(), false, true);
    return Rect{x, y, x + w, y + h};
  }

  std::optional<FilterResult> run_primitive(const ResolvedPrimitive& primitive,
                                            const std::vector<FilterResult*>& inputs,
                                            const std::vector<bool>& last_read, PixelRect needed) {
    const PrimitiveEntry& entry = *primitive.entry;
    // The default subregion (9.7).
    Rect fallback = definition_.region;
    const bool any_standard =
        std::any_of(inputs.begin(), inputs.end(), [](FilterResult* r) { return r->standard; });
    if (!inputs.empty() && !any_standard && entry.name != "feTile") {
      fallback = inputs.front()->user_subregion;
      for (FilterResult* r : inputs) fallback = union_of(fallback, r->user_subregion);
    }
    FilterResult result;
    result.space = primitive.color_space;
    result.user_subregion = subregion_of(primitive, fallback);
    result.subregion = pixel_rect(space_, result.user_subregion).intersect(region_);
    // Moving or blurring an image without colour gives one without colour.
    result.colorless =
        (entry.name == "feOffset" || entry.name == "feGaussianBlur" || entry.name == "feTile") &&
        inputs.front()->colorless;
    // A subregion without area gives a transparent result (9.7: zero width or height disables the effect).
    if (result.subregion.empty() || !(result.user_subregion.width() > 0.0) ||
        !(result.user_subregion.height() > 0.0)) {
      result.owned = acquire();
      return result;
    }
    // feFlood is one colour: it is drawn only when something other than feComposite reads it.
    if (entry.name == "feFlood") {
      result.constant = premultiplied(std::get<FloodParams>(primitive.params).color);
      result.constant_area = (*result.constant)[3] > 0.0f ? result.subregion.intersect(needed) : PixelRect{};
      return result;
    }
    // SourceAlpha is read straight from SourceGraphic by a blur, and made for anything else.
    const bool alpha_direct =
        entry.name == "feGaussianBlur" && !inputs.empty() && inputs[0]->alpha_of != nullptr;
    for (std::size_t k = alpha_direct ? 1 : 0; k < inputs.size(); ++k) {
      if (inputs[k]->alpha_of != nullptr) make_alpha(*inputs[k]);
    }
    // A flood read by feComposite stays a colour where it covers everything the composite may write (an
    // opaque flood over the composite's subregion, the shadow recipe's "flood in blurred alpha").
    std::array<std::array<float, 4>, 2> constants{};
    std::array<bool, 2> constant_input{false, false};
    for (std::size_t k = 0; k < inputs.size(); ++k) {
      FilterResult& r = *inputs[k];
      if (!r.constant) continue;
      const PixelRect written = result.subregion.intersect(needed);
      if (entry.name == "feComposite" && k < 2 && !r.constant_area.empty() &&
          r.constant_area.intersect(written) == written) {
        constants[k] = *r.constant;
        if (r.space != result.space)
          convert_pixels(constants[k].data(), constants[k].data(), 1, r.space, result.space);
        constant_input[k] = true;
      } else {
        make_constant(r);
      }
    }
    // The memory of the result: an input read for the last time (a per-pixel primitive computes in
    // place), or a fresh or given-back image. `stale` is where it may still hold old values; the primitive's
    // extent (what it writes) is set by its adapter, and the rest of `stale` is cleared after it.
    std::size_t reused = inputs.size();
    if (entry.in_place) {
      for (std::size_t k = 0; k < inputs.size() && reused == inputs.size(); ++k) {
        const FilterResult& r = *inputs[k];
        if (last_read[k] && !r.standard && r.borrowed == nullptr && r.is_in_space(result.space) &&
            r.owned.rgba.size() == sources_.source_graphic->rgba.size())
          reused = k;
      }
    }
    PixelRect stale;
    if (reused < inputs.size()) {
      result.owned = std::move(inputs[reused]->owned);
      inputs[reused]->owned = FilterImage();
      stale = result.owned.extent;  // the adapter reads it as the input's, then sets the result's
    } else {
      result.owned = acquire(entry.writes_whole_extent ? &stale : nullptr);
      // What the primitive may write; its adapter narrows this to where its result can be other than
      // transparent (primitive_table.h), and the primitives after it compute only there.
      result.owned.extent = result.subregion;
    }
    // Attributes in error (said when the filter was resolved): the filter's result is transparent black.
    if (!primitive.error.empty()) return std::nullopt;
    PrimitiveCall call{
        primitive.params, space_, result.subregion, result.user_subregion, result.space, nullptr, {},
        nullptr,          {},     environment_,     diagnostics_,          result.owned};
    const auto spare = [this](PixelRect* stale_part) { return acquire(stale_part); };
    const auto input_image = [&](std::size_t k) -> const FilterImage* {
      return k == reused ? &result.owned : &inputs[k]->in_space(result.space, spare);
    };
    if (entry.inputs == PrimitiveInputs::kMergeNodes) {
      // An input in the other colour space is converted a row at a time by the merge, unless its
      // conversion exists already: no image of its own for it.
      bool any_other = false;
      for (std::size_t k = 0; k < inputs.size(); ++k) {
        FilterResult& r = *inputs[k];
        const bool other = k != reused && !r.is_in_space(result.space) && !r.converted;
        call.merge_inputs.push_back(other ? &r.image() : input_image(k));
        call.merge_other_space.push_back(other);
        any_other = any_other || other;
      }
      if (!any_other) call.merge_other_space.clear();
    } else if (constant_input[0] || constant_input[1]) {
      call.in = constant_input[0] ? nullptr : input_image(0);
      call.in_constant = constant_input[0] ? constants[0].data() : nullptr;
      call.in2 = constant_input[1] ? nullptr : input_image(1);
      call.in2_constant = constant_input[1] ? constants[1].data() : nullptr;
      call.in_subregion = inputs[0]->subregion;
    } else {
      if (alpha_direct) {
        call.in = inputs[0]->alpha_of;
        call.in_alpha_only = true;
        call.in_subregion = inputs[0]->subregion;
      } else if (!inputs.empty()) {
        call.in = input_image(0);
        call.in_subregion = inputs[0]->subregion;
      }
      if (inputs.size() > 1) call.in2 = input_image(1);
    }
    call.needed = needed;
    entry.run(call);
    clear_stale(result.owned, stale);
    return result;
  }

  const FilterDefinition& definition_;
  const FilterSpace& space_;
  PixelRect region_;
  const FilterSources& sources_;
  const FilterEnvironment& environment_;
  Diagnostics& diagnostics_;
  std::vector<std::unique_ptr<FilterResult>> results_;
  struct Spare {
    FilterPixels pixels;
    PixelRect dirty;  // outside it the memory is zero
  };
  std::vector<Spare> spare_;                                // memory of released results
  std::unordered_map<std::string, int> standard_last_use_;  // the last primitive reading each standard input
  std::unordered_map<std::string, std::unique_ptr<FilterResult>> standard_;
};

// The matrix of grayscale() and sepia() (Filter Effects 1, section 13), amount a in [0, 1].
ColorMatrix grayscale_matrix(double a) noexcept {
  const double k = 1.0 - a;
  return {0.2126 + 0.7874 * k,
          0.7152 - 0.7152 * k,
          0.0722 - 0.0722 * k,
          0,
          0,
          0.2126 - 0.2126 * k,
          0.7152 + 0.2848 * k,
          0.0722 - 0.0722 * k,
          0,
          0,
          0.2126 - 0.2126 * k,
          0.7152 - 0.7152 * k,
          0.0722 + 0.9278 * k,
          0,
          0,
          0,
          0,
          0,
          1,
          0};
}

ColorMatrix sepia_matrix(double a) noexcept {
  const double k = 1.0 - a;
  return {0.393 + 0.607 * k,
          0.769 - 0.769 * k,
          0.189 - 0.189 * k,
          0,
          0,
          0.349 - 0.349 * k,
          0.686 + 0.314 * k,
          0.168 - 0.168 * k,
          0,
          0,
          0.272 - 0.272 * k,
          0.534 - 0.534 * k,
          0.131 + 0.869 * k,
          0,
          0,
          0,
          0,
          0,
          1,
          0};
}

}  // namespace

int peak_filter_images(const ResolvedFilter& plan) {
  if (!plan.unsupported.empty()) return 1;
  // Before primitive i runs, the images held are the results read at i or later, the standard inputs read
  // at i or later, and the new result; each of those may hold a conversion to the other colour space.
  const std::size_t n = plan.primitives.size();
  std::vector<int> starts(n + 2, 0);  // results alive before primitive i: a sweep over [j + 1, last_use]
  for (std::size_t j = 0; j < n; ++j) {
    const int last = plan.primitives[j].last_use;
    if (last > static_cast<int>(j)) {
      ++starts[j + 1];
      --starts[static_cast<std::size_t>(last) + 1];
    }
  }
  int peak = 1, results = 0;
  for (std::size_t i = 0; i < n; ++i) {
    results += starts[i];
    int live = 1 + results;
    for (const auto& [name, last] : plan.standard_last_use) live += last >= static_cast<int>(i) ? 1 : 0;
    peak = std::max(peak, 2 * live);
  }
  return peak;
}

PixelRect pixel_rect(const FilterSpace& space, const Rect& user) noexcept {
  const Point a = space.to_pixels({user.x0, user.y0}), b = space.to_pixels({user.x1, user.y1});
  constexpr double kSlack = 1e-4;
  // Clamped to the int range before conversion; the caller intersects with the filter image.
  const auto whole = [](double v) { return static_cast<int>(std::clamp(v, -1e9, 1e9)); };
  return PixelRect{
      whole(std::floor(std::min(a.x, b.x) + kSlack)), whole(std::floor(std::min(a.y, b.y) + kSlack)),
      whole(std::ceil(std::max(a.x, b.x) - kSlack)), whole(std::ceil(std::max(a.y, b.y) - kSlack))};
}

FilterImage run_filter(const FilterDefinition& definition, const FilterSpace& space, PixelRect region,
                       const FilterSources& sources, const FilterEnvironment& environment,
                       Diagnostics& diagnostics, ColorSpace* result_space) {
  return FilterRun(definition, space, region, sources, environment, diagnostics).run(result_space);
}

PixelRect function_input_needed(const FilterFunction& function, const FilterSpace& space,
                                PixelRect result_needed) noexcept {
  using Kind = FilterFunction::Kind;
  if (function.kind != Kind::kBlur && function.kind != Kind::kDropShadow) return result_needed;
  PixelRect wanted = result_needed;
  if (function.kind == Kind::kDropShadow) {
    // The source where it is (drawn over the shadow) and the shadow's source, moved back by the offset.
    wanted = wanted.unite(result_needed.moved(-whole_pixel_offset(space.x_to_pixels(function.dx)),
                                              -whole_pixel_offset(space.y_to_pixels(function.dy))));
  }
  return wanted.grown(blur_reach(space.x_to_pixels(function.amount)),
                      blur_reach(space.y_to_pixels(function.amount)));
}

FilterImage run_filter_function(const FilterFunction& function, const FilterSpace& space, PixelRect region,
                                const FilterImage& source, const Color& current_color, PixelRect needed) {
  using Kind = FilterFunction::Kind;
  FilterImage out(source.width, source.height);
  // The source outside the region is not seen (a copy cleared outside it, only when there is ink there).
  const PixelRect ink = source.extent.intersect(source.bounds());
  FilterImage clipped;
  const bool inside = ink.intersect(region) == ink;
  if (!inside) {
    clipped = source;
    clear_outside(clipped, region);
  }
  const FilterImage& input = inside ? source : clipped;
  // Every function but the blur and the shadow keeps a transparent pixel transparent: they compute only
  // over the input's ink.
  const PixelRect area = input.extent.intersect(region).intersect(needed);
  out.extent = area;
  const auto transfer = [&](const TransferFunction& rgb, const TransferFunction& alpha) {
    component_transfer(input, TransferFunctions{rgb, rgb, rgb, alpha}, area, out);
  };
  TransferFunction f;
  switch (function.kind) {
    case Kind::kUrl:
      return input;
    case Kind::kBlur: {
      const double sx = space.x_to_pixels(function.amount), sy = space.y_to_pixels(function.amount);
      // Read where the input has ink near the needed pixels; written only where needed.
      const long long reach_x = blur_reach(sx), reach_y = blur_reach(sy);
      const PixelRect around = needed.grown(reach_x, reach_y);
      const PixelRect read =
          input.extent.intersect(region).intersect(around).grown(reach_x, reach_y).intersect(around);
      out.extent = read.intersect(region).intersect(needed);
      gaussian_blur(input, read.intersect(region), sx, sy, EdgeMode::kNone, out, false, needed);
      break;
    }
    case Kind::kDropShadow: {
      const Color color = function.color.value_or(current_color);
      DropShadowParams params;
      params.sigma_x = space.x_to_pixels(function.amount);
      params.sigma_y = space.y_to_pixels(function.amount);
      params.dx = space.x_to_pixels(function.dx);
      params.dy = space.y_to_pixels(function.dy);
      params.color = FilterColor{static_cast<float>(color.r), static_cast<float>(color.g),
                                 static_cast<float>(color.b), static_cast<float>(color.a)};
      drop_shadow(input, params, region, out, needed);
      break;
    }
    case Kind::kBrightness:
      f.type = TransferFunction::Type::kLinear;
      f.slope = function.amount;
      transfer(f, TransferFunction{});
      break;
    case Kind::kContrast:
      f.type = TransferFunction::Type::kLinear;
      f.slope = function.amount;
      f.intercept = 0.5 - 0.5 * function.amount;
      transfer(f, TransferFunction{});
      break;
    case Kind::kInvert:
      f.type = TransferFunction::Type::kTable;
      f.table_values = {function.amount, 1.0 - function.amount};
      transfer(f, TransferFunction{});
      break;
    case Kind::kOpacity:
      f.type = TransferFunction::Type::kTable;
      f.table_values = {0.0, function.amount};
      transfer(TransferFunction{}, f);
      break;
    case Kind::kGrayscale:
      color_matrix(input, grayscale_matrix(function.amount), area, out);
      break;
    case Kind::kSepia:
      color_matrix(input, sepia_matrix(function.amount), area, out);
      break;
    case Kind::kSaturate:
      color_matrix(input, saturate_matrix(function.amount), area, out);
      break;
    case Kind::kHueRotate:
      color_matrix(input, hue_rotate_matrix(function.amount), area, out);
      break;
  }
  return out;
}

}  // namespace curvescan::svg::detail::filter
