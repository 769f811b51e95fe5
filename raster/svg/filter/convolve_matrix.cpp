#include "convolve_matrix.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace curvescan::svg::detail::filter {

namespace {

/// The source coordinate for `i` (possibly outside [lo, hi)) under the edge mode; -1 for "transparent".
int edge_index(int i, int lo, int hi, EdgeMode mode) noexcept {
  if (i >= lo && i < hi) return i;
  switch (mode) {
    case EdgeMode::kDuplicate:
      return std::clamp(i, lo, hi - 1);
    case EdgeMode::kWrap: {
      const int n = hi - lo;
      const int r = (i - lo) % n;
      return lo + (r < 0 ? r + n : r);
    }
    case EdgeMode::kNone:
      break;
  }
  return -1;
}

/// One target coordinate: absent -> floor(order / 2); must be an integer in [0, order).
bool read_target(const pugi::xml_node& primitive, const char* name, int order, int& target,
                 std::string& error) {
  target = order / 2;
  if (!primitive.attribute(name)) return true;
  const auto value = primitive_number(primitive, name);
  if (!value || !is_integer_value(*value) || *value < 0.0 || *value >= order) {
    error = std::string("feConvolveMatrix: ") + name + " must be an integer from 0 to the order minus 1";
    return false;
  }
  target = static_cast<int>(*value);
  return true;
}

/// std::clamp that also maps NaN (inf - inf from kernels of 1e308) to `lo` instead of passing it through.
double clamp_or_low(double v, double lo, double hi) noexcept {
  return v >= lo ? std::min(v, hi) : lo;
}

}  // namespace

std::optional<ConvolveMatrixParams> read_convolve_matrix(const pugi::xml_node& primitive,
                                                         std::string& error) {
  ConvolveMatrixParams params;
  if (primitive.attribute("order")) {
    // Filter Effects 1: integers greater than zero; "values that are not integers will be truncated".
    const auto order = primitive_number_pair(primitive, "order");
    const double order_x = order ? std::trunc(order->x) : 0.0, order_y = order ? std::trunc(order->y) : 0.0;
    if (order_x < 1.0 || order_y < 1.0) {
      error = "feConvolveMatrix: order must be one or two numbers of at least 1";
      return std::nullopt;
    }
    if (order_x > kMaxConvolveOrder || order_y > kMaxConvolveOrder) {
      error = "feConvolveMatrix: an order above " + std::to_string(kMaxConvolveOrder) + " is not supported";
      return std::nullopt;
    }
    params.order_x = static_cast<int>(order_x);
    params.order_y = static_cast<int>(order_y);
  }
  auto kernel = primitive_number_list(primitive, "kernelMatrix");
  if (!kernel || kernel->size() != static_cast<std::size_t>(params.order_x) * params.order_y) {
    error = "feConvolveMatrix: kernelMatrix must hold orderX * orderY numbers";
    return std::nullopt;
  }
  params.kernel = std::move(*kernel);

  double sum = 0.0, magnitude = 0.0;
  for (const double k : params.kernel) {
    sum += k;
    magnitude += std::fabs(k);
  }
  // A kernel written to sum to zero rarely does in binary floating point (0.1 * 8 - 0.8 is 1e-16, and a
  // divisor of 1e-16 saturates every pixel): a sum below the rounding error of adding the entries is zero.
  const bool zero_sum = std::fabs(sum) <= 1e-12 * magnitude;
  const double divisor = primitive_number(primitive, "divisor").value_or(0.0);
  // Filter Effects 1: a divisor of 0 is replaced by the default, the kernel's sum, or 1 when that is 0. A
  // sum that overflows to infinity (hostile kernels of 1e308) would divide everything to 0; use 1.
  params.divisor = divisor != 0.0 ? divisor : (!zero_sum && std::isfinite(sum) ? sum : 1.0);
  params.bias = primitive_number(primitive, "bias").value_or(0.0);

  if (!read_target(primitive, "targetX", params.order_x, params.target_x, error)) return std::nullopt;
  if (!read_target(primitive, "targetY", params.order_y, params.target_y, error)) return std::nullopt;

  params.edge_mode = parse_edge_mode(primitive.attribute("edgeMode").value()).value_or(EdgeMode::kDuplicate);
  params.preserve_alpha = std::string_view(primitive.attribute("preserveAlpha").value()) == "true";

  if (primitive.attribute("kernelUnitLength")) {
    params.kernel_unit_length = primitive_number_pair(primitive, "kernelUnitLength");
    if (params.kernel_unit_length &&
        (params.kernel_unit_length->x <= 0.0 || params.kernel_unit_length->y <= 0.0)) {
      error = "feConvolveMatrix: kernelUnitLength must be positive";
      return std::nullopt;
    }
  }
  return params;
}

void render_convolve_matrix(const ConvolveMatrixParams& params, const FilterSpace& /*space*/,
                            PixelRect subregion, const FilterImage& in, FilterImage& out,
                            std::optional<PixelRect> written, std::optional<PixelRect> input_area) {
  const PixelRect area = subregion.intersect(out.bounds()).intersect(in.bounds());
  const PixelRect computed = written ? area.intersect(*written) : area;
  if (computed.empty()) return;
  const int ox = params.order_x, oy = params.order_y;
  // The input image and its edge (for edgeMode): where the input exists, which may reach beyond this
  // primitive's subregion. An input that exists nowhere has no edge to extend: every sample is transparent.
  const PixelRect source_area = input_area.value_or(area).intersect(in.bounds());
  const EdgeMode edge_mode = source_area.empty() ? EdgeMode::kNone : params.edge_mode;
  const int width = source_area.width(), height = source_area.height();

  // With preserveAlpha the colour is convolved unpremultiplied: unpremultiply the area once.
  std::vector<float> source;
  if (params.preserve_alpha) {
    source.resize(static_cast<std::size_t>(width) * height * 4);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const float* p = in.pixel(source_area.x0 + x, source_area.y0 + y);
        float* s = source.data() + 4 * (static_cast<std::size_t>(y) * width + x);
        for (int c = 0; c < 3; ++c) s[c] = p[3] > 0.0f ? std::min(p[c] / p[3], 1.0f) : 0.0f;
        s[3] = p[3];
      }
    }
  }
  const auto sample = [&](int x, int y) -> const float* {
    if (params.preserve_alpha)
      return source.data() +
             4 * (static_cast<std::size_t>(y - source_area.y0) * width + (x - source_area.x0));
    return in.pixel(x, y);
  };

  // The source column of each output column and kernel column, resolved once per render (-1: transparent).
  std::vector<int> columns(static_cast<std::size_t>(area.width()) * ox);
  for (int x = 0; x < area.width(); ++x)
    for (int j = 0; j < ox; ++j)
      columns[static_cast<std::size_t>(x) * ox + j] =
          edge_index(area.x0 + x - params.target_x + j, source_area.x0, source_area.x1, edge_mode);

  const int channels = params.preserve_alpha ? 3 : 4;
  for (int y = computed.y0; y < computed.y1; ++y) {
    for (int x = computed.x0; x < computed.x1; ++x) {
      std::array<double, 4> sum{};
      for (int i = 0; i < oy; ++i) {
        const int sy = edge_index(y - params.target_y + i, source_area.y0, source_area.y1, edge_mode);
        if (sy < 0) continue;
        // kernelMatrix(orderX - J - 1, orderY - I - 1): column orderX - J - 1 of row orderY - I - 1.
        const double* kernel_row = params.kernel.data() + static_cast<std::size_t>(oy - i - 1) * ox;
        const int* column = columns.data() + static_cast<std::size_t>(x - area.x0) * ox;
        for (int j = 0; j < ox; ++j) {
          if (column[j] < 0) continue;
          const double k = kernel_row[ox - j - 1];
          const float* p = sample(column[j], sy);
          for (int c = 0; c < channels; ++c) sum[static_cast<std::size_t>(c)] += k * p[c];
        }
      }
      float* result = out.pixel(x, y);
      if (params.preserve_alpha) {
        const float alpha = in.pixel(x, y)[3];
        for (int c = 0; c < 3; ++c)
          result[c] = static_cast<float>(clamp_or_low(
                          sum[static_cast<std::size_t>(c)] / params.divisor + params.bias, 0.0, 1.0)) *
                      alpha;
        result[3] = alpha;
      } else {
        // ALPHA in "bias * ALPHA" is the result's alpha before clamping, as librsvg and resvg take it.
        const double raw_alpha = sum[3] / params.divisor + params.bias;
        const double alpha = clamp_or_low(raw_alpha, 0.0, 1.0);
        for (int c = 0; c < 3; ++c)
          result[c] = static_cast<float>(clamp_or_low(
              sum[static_cast<std::size_t>(c)] / params.divisor + params.bias * raw_alpha, 0.0, alpha));
        result[3] = static_cast<float>(alpha);
      }
    }
  }
}

}  // namespace curvescan::svg::detail::filter
