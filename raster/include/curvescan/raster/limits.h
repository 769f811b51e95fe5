// Limits: the largest inputs curvescan's raster library accepts, checked before anything is allocated.
//
// Every limit here is refused with ErrorKind::kLimitExceeded and a message naming the limit, so that a
// hostile or mistaken input (a PNG header claiming 100000 x 100000 pixels, a path with a degree-10000
// segment) fails fast instead of exhausting memory or time.
#pragma once

#include <cstdint>

namespace curvescan {

/// Largest width or height of an Image that curvescan reads, writes or renders into. 32767 is the
/// image-surface limit of Cairo and pixman, the oracle, so every image we make can be compared with it.
inline constexpr int kMaxImageDimension = 32767;

/// Largest number of pixels (width x height) of such an Image: 2^26 pixels = 256 MiB of RGBA8, which is
/// e.g. 8192 x 8192 or 32767 x 2048. Keeps a test machine alive when a file lies about its size.
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 26;

/// Deepest nesting of Canvas layers (push_layer, for group opacity). Each layer is an RGBA8 image of at
/// most the canvas size, so 16 bounds the memory at 16 canvases; SVG content nests opacity groups a few
/// levels deep, and a hostile document nesting 10^5 groups is refused instead of exhausting memory.
inline constexpr int kMaxLayerDepth = 16;

/// Deepest nesting of Canvas clip masks (push_clip). Each is one byte per canvas pixel; 32 bounds the
/// memory at 8 RGBA canvases while leaving room for clipPaths nested inside clipped groups.
inline constexpr int kMaxClipDepth = 32;

/// Highest degree of one Bézier or rational Bézier segment a Path accepts. Evaluation and flattening are
/// quadratic in the degree (de Casteljau; Umetani, *Parametric Curve*, section 2.1), and the B-spline/NURBS
/// segments of the course notes are of low degree (cubic is the common case); 64 leaves ample room without
/// letting one segment cost seconds.
inline constexpr int kMaxPathCurveDegree = 64;

/// Most dashes one stroke or dash_path() call may produce. A dash pattern with a tiny period on a long
/// path (a 0.001-unit pattern on a 10^7-unit path is 10^10 dashes) is refused before any dash is made,
/// with kLimitExceeded, instead of exhausting memory or time. 2^20 dashes of a few dozen points each is
/// already ~100 MB of outline.
inline constexpr std::int64_t kMaxDashSegments = std::int64_t{1} << 20;

/// Default budget of flattened line segments (rasterizer edges) for one render: every fill, stroke
/// outline and clip path drawn on one Canvas counts. The rasterizer's work and memory grow with its edges
/// (a set of mutually crossing edges costs more than linear time), so an input that flattens to more
/// is refused instead of running for minutes. 2^22 is four times the largest benchmark document (10^6
/// segments, docs/benchmarks.md) and equals kMaxFlattenSegments, the most one curve may make.
inline constexpr std::int64_t kDefaultMaxRenderSegments = std::int64_t{1} << 22;

/// Default memory budget of one render in bytes: the canvas, its layers and clip masks, and the edges
/// of the fill in progress. 1 GiB holds the largest default SVG canvas (2^24 pixels = 64 MiB) with 15
/// opacity layers, or the largest image (kMaxImagePixels = 256 MiB) with three.
inline constexpr std::int64_t kDefaultMaxRenderMemoryBytes = std::int64_t{1} << 30;

/// Bytes one rasterizer edge may cost at its peak: the rasterizer keeps, per edge, the clipped edge
/// (48 bytes) twice while bucketing (edges and sorted_edges), a 16-byte sort key, four 4-byte indices
/// (new_index, active, band_active, pending_edges) and a 24-byte pending boundary run: 152 bytes
/// (rasterizer_impl.h, ScanState). 160 leaves room for the polyline scratch space.
inline constexpr std::int64_t kRenderBytesPerEdge = 160;

/// Per-render budgets a Canvas enforces (canvas.h), each refused with kLimitExceeded and a message naming
/// the limit and the command-line flag that raises it (docs/limits.md). A default-constructed value holds
/// the documented defaults; unlimited() disables the budgets (the library's own hard limits above stay).
struct RenderLimits {
  /// Flattened line segments over the whole render (curvescan --max-segments).
  std::int64_t max_segments = kDefaultMaxRenderSegments;
  /// Canvas + layers + clip masks + edges of one fill, in bytes (curvescan --max-memory, in MiB).
  std::int64_t max_memory_bytes = kDefaultMaxRenderMemoryBytes;
  /// Dashes of one stroke (curvescan --max-dashes); at most kMaxDashSegments, the dasher's own limit.
  std::int64_t max_dashes = kMaxDashSegments;

  [[nodiscard]] static constexpr RenderLimits unlimited() noexcept {
    return {INT64_MAX, INT64_MAX, kMaxDashSegments};
  }
};

/// True when a width x height image is within kMaxImageDimension and kMaxImagePixels (and non-empty).
[[nodiscard]] constexpr bool image_size_within_limits(std::int64_t width, std::int64_t height) noexcept {
  return width >= 1 && height >= 1 && width <= kMaxImageDimension && height <= kMaxImageDimension &&
         width * height <= kMaxImagePixels;
}

}  // namespace curvescan
