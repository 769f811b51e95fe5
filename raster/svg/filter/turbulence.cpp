// The reference algorithm of Filter Effects 1, section 15.26 (identical in SVG 1.1, section 15.25),
// restated. Names follow the reference code so the two can be read side by side: the lattice selector is
// a random permutation of 0..255, each of the four colour channels has 256 random unit gradients, noise2 is
// classic 2D Perlin noise with the s-curve 3t^2 - 2t^3, and PerlinN = 4096 is added to coordinates so they
// are positive before the integer part is taken.
//
// The reference noise2 reduces the lattice cell modulo 256 before comparing it with the stitch wrap point
// (about 4096 + the tile's lattice extent), so as printed the comparison almost never succeeds and
// stitchTiles changes only the frequencies. resvg compares the unreduced cell and reduces afterwards,
// which is what makes the tile's opposite edges continue each other; this file does the same. Without
// stitching the two orders give identical values. (resvg and librsvg then pass the pixel's offset as the
// tile origin, which again disables the wrap for a tile at the origin; here the tile is the subregion, as
// the specification describes it.)
//
// Two deliberate departures, both only on inputs where the reference code has undefined behaviour in C:
// - The integer part of a coordinate is taken in 64 bits (the reference converts to int, which overflows
//   for coordinates beyond 2^31 / frequency); within the int range the result is identical.
// - A gradient drawn as (0, 0) cannot be normalized (the reference divides 0 by 0); it stays (0, 0), as
//   Skia does.
#include "turbulence.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "primitive_numbers.h"

namespace curvescan::svg::detail::filter {

namespace {

constexpr int kBSize = 0x100;
constexpr int kBMask = 0xff;
constexpr int kPerlinN = 0x1000;
constexpr std::int64_t kRandM = 2147483647;  // 2^31 - 1
constexpr std::int64_t kRandA = 16807;       // 7^5, a primitive root of kRandM
constexpr std::int64_t kRandQ = 127773;      // kRandM / kRandA
constexpr std::int64_t kRandR = 2836;        // kRandM % kRandA

/// The reference code's setup_seed: brings any seed into 1 .. kRandM - 1.
std::int64_t setup_seed(std::int64_t seed) noexcept {
  if (seed <= 0) seed = -(seed % (kRandM - 1)) + 1;
  if (seed > kRandM - 1) seed = kRandM - 1;
  return seed;
}

/// One step of the Park-Miller "minimal standard" generator, Schrage's method as in the reference code.
std::int64_t next_random(std::int64_t seed) noexcept {
  std::int64_t result = kRandA * (seed % kRandQ) - kRandR * (seed / kRandQ);
  if (result <= 0) result += kRandM;
  return result;
}

struct StitchInfo {
  std::int64_t width = 0;  // how much to subtract to wrap
  std::int64_t height = 0;
  std::int64_t wrap_x = 0;  // the lattice coordinate at which to wrap
  std::int64_t wrap_y = 0;
};

/// Integer part (towards zero, as C's int conversion) and fraction of a lattice coordinate. Coordinates
/// beyond 2^62 (only reachable from absurd frequencies and octaves) keep only their parity-free value 0.
void split_coordinate(double t, std::int64_t& whole, double& fraction) noexcept {
  constexpr double kLimit = 4.0e18;
  if (!(std::fabs(t) < kLimit)) {
    whole = 0;
    fraction = 0.0;
    return;
  }
  const double truncated = std::trunc(t);
  whole = static_cast<std::int64_t>(truncated);
  fraction = t - truncated;
}

/// A stitch bookkeeping value (a double in the reference code, converted to int) kept within a range where
/// doubling it kMaxTurbulenceOctaves times cannot overflow 64 bits.
std::int64_t to_stitch_int(double v) noexcept {
  constexpr double kLimit = 1.0e11;
  if (!(v > -kLimit)) return static_cast<std::int64_t>(-kLimit);
  if (!(v < kLimit)) return static_cast<std::int64_t>(kLimit);
  return static_cast<std::int64_t>(v);
}

class PerlinNoise {
 public:
  explicit PerlinNoise(std::int64_t seed) noexcept {
    seed = setup_seed(seed);
    int i = 0;
    for (int k = 0; k < 4; ++k) {
      for (i = 0; i < kBSize; ++i) {
        lattice_[i] = i;
        for (int j = 0; j < 2; ++j) {
          seed = next_random(seed);
          gradient_[k][i][j] = static_cast<double>((seed % (kBSize + kBSize)) - kBSize) / kBSize;
        }
        const double s =
            std::sqrt(gradient_[k][i][0] * gradient_[k][i][0] + gradient_[k][i][1] * gradient_[k][i][1]);
        if (s > 0.0) {
          gradient_[k][i][0] /= s;
          gradient_[k][i][1] /= s;
        }
      }
    }
    // Shuffle the lattice: i runs from 255 down to 1 (the reference's `while(--i)` after the loop above).
    while (--i) {
      const int k = lattice_[i];
      seed = next_random(seed);
      const int j = static_cast<int>(seed % kBSize);
      lattice_[i] = lattice_[j];
      lattice_[j] = k;
    }
    for (i = 0; i < kBSize + 2; ++i) {
      lattice_[kBSize + i] = lattice_[i];
      for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 2; ++j) gradient_[k][kBSize + i][j] = gradient_[k][i][j];
    }
  }

  [[nodiscard]] double noise2(int channel, double vx, double vy, const StitchInfo* stitch) const noexcept {
    std::int64_t whole_x = 0, whole_y = 0;
    double rx0 = 0.0, ry0 = 0.0;
    split_coordinate(vx + kPerlinN, whole_x, rx0);
    split_coordinate(vy + kPerlinN, whole_y, ry0);
    // The lattice cell, not yet reduced modulo 256: see the header comment on stitching.
    std::int64_t bx0 = whole_x;
    std::int64_t bx1 = bx0 + 1;
    std::int64_t by0 = whole_y;
    std::int64_t by1 = by0 + 1;
    const double rx1 = rx0 - 1.0;
    const double ry1 = ry0 - 1.0;
    if (stitch != nullptr) {
      if (bx0 >= stitch->wrap_x) bx0 -= stitch->width;
      if (bx1 >= stitch->wrap_x) bx1 -= stitch->width;
      if (by0 >= stitch->wrap_y) by0 -= stitch->height;
      if (by1 >= stitch->wrap_y) by1 -= stitch->height;
    }
    bx0 &= kBMask;
    bx1 &= kBMask;
    by0 &= kBMask;
    by1 &= kBMask;
    const int i = lattice_[bx0];
    const int j = lattice_[bx1];
    const int b00 = lattice_[i + by0];
    const int b10 = lattice_[j + by0];
    const int b01 = lattice_[i + by1];
    const int b11 = lattice_[j + by1];
    const double sx = s_curve(rx0);
    const double sy = s_curve(ry0);
    const auto& g = gradient_[channel];
    double u = rx0 * g[b00][0] + ry0 * g[b00][1];
    double v = rx1 * g[b10][0] + ry0 * g[b10][1];
    const double a = lerp(sx, u, v);
    u = rx0 * g[b01][0] + ry1 * g[b01][1];
    v = rx1 * g[b11][0] + ry1 * g[b11][1];
    const double b = lerp(sx, u, v);
    return lerp(sy, a, b);
  }

 private:
  static double s_curve(double t) noexcept { return t * t * (3.0 - 2.0 * t); }
  static double lerp(double t, double a, double b) noexcept { return a + t * (b - a); }

  static constexpr int kLength = kBSize + kBSize + 2;
  std::array<int, kLength> lattice_{};
  std::array<std::array<std::array<double, 2>, kLength>, 4> gradient_{};
};

/// The reference code's frequency adjustment for stitching: the nearer of floor and ceil of tile * f,
/// divided back by the tile size, so that the tile holds a whole number of lattice cells.
double stitch_frequency(double frequency, double tile_size) noexcept {
  if (frequency == 0.0) return frequency;
  const double lo = std::floor(tile_size * frequency) / tile_size;
  const double hi = std::ceil(tile_size * frequency) / tile_size;
  return frequency / lo < hi / frequency ? lo : hi;
}

}  // namespace

std::optional<TurbulenceParams> read_turbulence(const pugi::xml_node& primitive, std::string& error) {
  TurbulenceParams params;
  if (const auto frequency = primitive_number_pair(primitive, "baseFrequency")) {
    if (frequency->x < 0.0 || frequency->y < 0.0) {
      error = "feTurbulence: a negative baseFrequency is an error";
      return std::nullopt;
    }
    params.base_frequency_x = frequency->x;
    params.base_frequency_y = frequency->y;
  }
  if (const auto octaves = primitive_number(primitive, "numOctaves"); octaves && is_integer_value(*octaves))
    params.num_octaves =
        static_cast<int>(std::clamp(*octaves, 0.0, static_cast<double>(kMaxTurbulenceOctaves)));
  if (const auto seed = primitive_number(primitive, "seed")) {
    // Truncated towards zero (Filter Effects 1); beyond the generator's range setup_seed would fold it
    // anyway, so clamping first only keeps the conversion defined.
    params.seed = static_cast<long long>(std::trunc(std::clamp(*seed, -4.0e18, 4.0e18)));
  }
  const std::string_view stitch = primitive.attribute("stitchTiles").value();
  params.stitch_tiles = stitch == "stitch";
  const std::string_view type = primitive.attribute("type").value();
  params.fractal_noise = type == "fractalNoise";
  return params;
}

void render_turbulence(const TurbulenceParams& params, const FilterSpace& space, PixelRect subregion,
                       FilterImage& out, std::optional<PixelRect> written) {
  const PixelRect area = subregion.intersect(out.bounds());
  const PixelRect write = written ? area.intersect(*written) : area;
  if (write.empty()) return;
  const PerlinNoise noise(params.seed);
  const int octaves = std::clamp(params.num_octaves, 0, kMaxTurbulenceOctaves);

  double frequency_x = params.base_frequency_x;
  double frequency_y = params.base_frequency_y;
  StitchInfo stitch;
  const StitchInfo* stitch_pointer = nullptr;
  if (params.stitch_tiles) {
    // The tile is the primitive subregion in user space (the spec's fTileX .. fTileHeight).
    const double tile_x = space.origin_x + area.x0 / space.scale_x;
    const double tile_y = space.origin_y + area.y0 / space.scale_y;
    const double tile_width = area.width() / space.scale_x;
    const double tile_height = area.height() / space.scale_y;
    frequency_x = stitch_frequency(frequency_x, tile_width);
    frequency_y = stitch_frequency(frequency_y, tile_height);
    stitch.width = to_stitch_int(tile_width * frequency_x + 0.5);
    stitch.wrap_x = to_stitch_int(tile_x * frequency_x + kPerlinN + static_cast<double>(stitch.width));
    stitch.height = to_stitch_int(tile_height * frequency_y + 0.5);
    stitch.wrap_y = to_stitch_int(tile_y * frequency_y + kPerlinN + static_cast<double>(stitch.height));
    stitch_pointer = &stitch;
  }

  for (int y = write.y0; y < write.y1; ++y) {
    const double user_y = space.origin_y + y / space.scale_y;
    for (int x = write.x0; x < write.x1; ++x) {
      const double user_x = space.origin_x + x / space.scale_x;
      std::array<double, 4> value{};
      for (int channel = 0; channel < 4; ++channel) {
        // The reference turbulence(): octaves at doubling frequency and halving weight; the stitch
        // values double with the lattice (subtracting PerlinN once is the reference's simplification).
        StitchInfo octave_stitch = stitch;
        const StitchInfo* octave_stitch_pointer = stitch_pointer != nullptr ? &octave_stitch : nullptr;
        double vx = user_x * frequency_x;
        double vy = user_y * frequency_y;
        double ratio = 1.0;
        double sum = 0.0;
        for (int octave = 0; octave < octaves; ++octave) {
          const double n = noise.noise2(channel, vx, vy, octave_stitch_pointer);
          sum += (params.fractal_noise ? n : std::fabs(n)) / ratio;
          vx *= 2.0;
          vy *= 2.0;
          ratio *= 2.0;
          if (octave_stitch_pointer != nullptr) {
            octave_stitch.width *= 2;
            octave_stitch.wrap_x = 2 * octave_stitch.wrap_x - kPerlinN;
            octave_stitch.height *= 2;
            octave_stitch.wrap_y = 2 * octave_stitch.wrap_y - kPerlinN;
          }
        }
        // fractalNoise maps [-1, 1] to [0, 1]; turbulence is already in [0, 1] (both clamped).
        value[static_cast<std::size_t>(channel)] =
            std::clamp(params.fractal_noise ? (sum + 1.0) / 2.0 : sum, 0.0, 1.0);
      }
      // The noise is unpremultiplied RGBA; the filter image is premultiplied.
      float* pixel = out.pixel(x, y);
      const double alpha = value[3];
      pixel[0] = static_cast<float>(value[0] * alpha);
      pixel[1] = static_cast<float>(value[1] * alpha);
      pixel[2] = static_cast<float>(value[2] * alpha);
      pixel[3] = static_cast<float>(alpha);
    }
  }
}

}  // namespace curvescan::svg::detail::filter
