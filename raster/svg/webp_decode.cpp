// WebP decoding (webp_decode.h). libwebp writes straight RGBA into a buffer of ours, which is then
// premultiplied in place (pixel_format.h rounds as every compositing step does).
#include "webp_decode.h"

#include <webp/decode.h>

#include <cstring>
#include <string>
#include <vector>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/pixel_format.h"

namespace curvescan::svg::detail {

bool is_webp(std::span<const std::uint8_t> bytes) noexcept {
  return bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 &&
         std::memcmp(bytes.data() + 8, "WEBP", 4) == 0;
}

std::optional<std::pair<std::int64_t, std::int64_t>> webp_dimensions(
    std::span<const std::uint8_t> bytes) noexcept {
  int width = 0, height = 0;
  if (!is_webp(bytes) || !WebPGetInfo(bytes.data(), bytes.size(), &width, &height)) return std::nullopt;
  return std::pair{std::int64_t{width}, std::int64_t{height}};
}

Result<Image> decode_webp(std::span<const std::uint8_t> bytes, std::int64_t max_pixels) {
  WebPBitstreamFeatures features{};
  if (!is_webp(bytes) || WebPGetFeatures(bytes.data(), bytes.size(), &features) != VP8_STATUS_OK)
    return Error{ErrorKind::kCorruptInput, "not a readable WebP image"};
  if (features.has_animation)
    return Error{ErrorKind::kCorruptInput, "an animated WebP image is not supported"};
  const std::int64_t width = features.width, height = features.height;
  if (width < 1 || height < 1) return Error{ErrorKind::kCorruptInput, "a WebP image of no pixels"};
  if (width > kMaxImageDimension || height > kMaxImageDimension || width * height > max_pixels) {
    return Error{ErrorKind::kLimitExceeded, "a WebP image of " + std::to_string(width) + " x " +
                                                std::to_string(height) + " pixels is beyond the pixel limit"};
  }
  Image image(static_cast<int>(width), static_cast<int>(height));
  static_assert(sizeof(Rgba8) == 4, "Rgba8 is four bytes, r g b a, as libwebp's RGBA output");
  auto* out = reinterpret_cast<std::uint8_t*>(image.row(0));
  const std::size_t stride = static_cast<std::size_t>(width) * 4;
  if (WebPDecodeRGBAInto(bytes.data(), bytes.size(), out, stride * static_cast<std::size_t>(height),
                         static_cast<int>(stride)) == nullptr)
    return Error{ErrorKind::kCorruptInput, "not a readable WebP image (the data is broken)"};
  for (int y = 0; y < height; ++y) {
    Rgba8* row = image.row(y);
    for (int x = 0; x < width; ++x)
      row[x] = premultiply(StraightRgba8{row[x].r, row[x].g, row[x].b, row[x].a});
  }
  return image;
}

}  // namespace curvescan::svg::detail
