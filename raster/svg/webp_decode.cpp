// WebP decoding (webp_decode.h). libwebp writes straight RGBA (into a buffer of ours for a still image, into
// its animation decoder's canvas for an animation), which is then premultiplied (pixel_format.h rounds as
// every compositing step does).
#include "webp_decode.h"

#include <webp/decode.h>
#include <webp/demux.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/pixel_format.h"

namespace curvescan::svg::detail {
namespace {

struct AnimDecoderDeleter {
  void operator()(WebPAnimDecoder* decoder) const noexcept { WebPAnimDecoderDelete(decoder); }
};

// Straight RGBA rows (stride width x 4) premultiplied into `image`.
void premultiply_into(const std::uint8_t* rgba, Image& image) {
  for (int y = 0; y < image.height(); ++y) {
    Rgba8* row = image.row(y);
    const std::uint8_t* in = rgba + static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()) * 4;
    for (int x = 0; x < image.width(); ++x, in += 4)
      row[x] = premultiply(StraightRgba8{in[0], in[1], in[2], in[3]});
  }
}

// The first frame of an animation, composited by libwebpdemux onto the transparent canvas.
Result<Image> decode_first_frame(std::span<const std::uint8_t> bytes, Image image) {
  WebPAnimDecoderOptions options;
  if (!WebPAnimDecoderOptionsInit(&options))
    return Error{ErrorKind::kCorruptInput, "libwebp's animation decoder is unusable"};
  options.color_mode = MODE_RGBA;
  options.use_threads = 0;
  const WebPData data{bytes.data(), bytes.size()};
  const std::unique_ptr<WebPAnimDecoder, AnimDecoderDeleter> decoder(WebPAnimDecoderNew(&data, &options));
  WebPAnimInfo info{};
  if (!decoder || !WebPAnimDecoderGetInfo(decoder.get(), &info))
    return Error{ErrorKind::kCorruptInput, "not a readable WebP animation"};
  if (info.canvas_width != static_cast<std::uint32_t>(image.width()) ||
      info.canvas_height != static_cast<std::uint32_t>(image.height()))
    return Error{ErrorKind::kCorruptInput, "not a readable WebP animation (its canvas size is inconsistent)"};
  std::uint8_t* frame = nullptr;
  int timestamp = 0;
  if (!WebPAnimDecoderHasMoreFrames(decoder.get()) ||
      !WebPAnimDecoderGetNext(decoder.get(), &frame, &timestamp) || frame == nullptr)
    return Error{ErrorKind::kCorruptInput, "not a readable WebP animation (its first frame is broken)"};
  premultiply_into(frame, image);
  return image;
}

}  // namespace

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

Result<Image> decode_webp(std::span<const std::uint8_t> bytes, std::int64_t max_pixels, bool* animated) {
  WebPBitstreamFeatures features{};
  if (!is_webp(bytes) || WebPGetFeatures(bytes.data(), bytes.size(), &features) != VP8_STATUS_OK)
    return Error{ErrorKind::kCorruptInput, "not a readable WebP image"};
  if (animated != nullptr) *animated = features.has_animation != 0;
  const std::int64_t width = features.width, height = features.height;
  if (width < 1 || height < 1) return Error{ErrorKind::kCorruptInput, "a WebP image of no pixels"};
  if (width > kMaxImageDimension || height > kMaxImageDimension || width * height > max_pixels) {
    return Error{ErrorKind::kLimitExceeded, "a WebP image of " + std::to_string(width) + " x " +
                                                std::to_string(height) + " pixels is beyond the pixel limit"};
  }
  Image image(static_cast<int>(width), static_cast<int>(height));
  if (features.has_animation) return decode_first_frame(bytes, std::move(image));
  static_assert(sizeof(Rgba8) == 4, "Rgba8 is four bytes, r g b a, as libwebp's RGBA output");
  auto* out = reinterpret_cast<std::uint8_t*>(image.row(0));
  const std::size_t stride = static_cast<std::size_t>(width) * 4;
  if (WebPDecodeRGBAInto(bytes.data(), bytes.size(), out, stride * static_cast<std::size_t>(height),
                         static_cast<int>(stride)) == nullptr)
    return Error{ErrorKind::kCorruptInput, "not a readable WebP image (the data is broken)"};
  premultiply_into(out, image);  // in place: each pixel is read before it is written
  return image;
}

}  // namespace curvescan::svg::detail
