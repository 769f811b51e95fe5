// WebP decoding (webp_decode.h). libwebp writes straight RGBA into the returned image's own pixels (the whole
// image for a still one, the first frame's rectangle of the canvas for an animation), which are then
// premultiplied in place (pixel_format.h rounds as every compositing step does).
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

struct DemuxDeleter {
  void operator()(WebPDemuxer* demuxer) const noexcept { WebPDemuxDelete(demuxer); }
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

// The first frame of an animation on its transparent canvas, decoded straight into `image` (the canvas's
// size). RFC 9649 2.7: the canvas starts transparent (the background colour is a hint a decoder may
// ignore, as libwebp's animation decoder does) and the first frame is placed at its offset; blended or not
// over transparency it is the frame's own pixels, and disposal only acts after it. So the frame is decoded
// into the canvas's rows at its offset, and no other buffer is needed: libwebpdemux's animation decoder
// would hold two canvases of its own (its output and the previous frame), memory the render's budget
// (limits.h) does not see.
Result<Image> decode_first_frame(std::span<const std::uint8_t> bytes, Image image) {
  const WebPData data{bytes.data(), bytes.size()};
  const std::unique_ptr<WebPDemuxer, DemuxDeleter> demuxer(WebPDemux(&data));
  if (!demuxer) return Error{ErrorKind::kCorruptInput, "not a readable WebP animation"};
  if (WebPDemuxGetI(demuxer.get(), WEBP_FF_CANVAS_WIDTH) != static_cast<std::uint32_t>(image.width()) ||
      WebPDemuxGetI(demuxer.get(), WEBP_FF_CANVAS_HEIGHT) != static_cast<std::uint32_t>(image.height()))
    return Error{ErrorKind::kCorruptInput, "not a readable WebP animation (its canvas size is inconsistent)"};
  WebPIterator frame{};
  if (!WebPDemuxGetFrame(demuxer.get(), 1, &frame))
    return Error{ErrorKind::kCorruptInput, "not a readable WebP animation (it has no frame)"};
  // WebPDemux validates a complete file's frames to lie inside the canvas; checked again before writing.
  const bool inside = frame.x_offset >= 0 && frame.y_offset >= 0 && frame.width > 0 && frame.height > 0 &&
                      frame.x_offset + frame.width <= image.width() &&
                      frame.y_offset + frame.height <= image.height();
  const std::size_t stride = static_cast<std::size_t>(image.width()) * 4;
  auto* canvas = reinterpret_cast<std::uint8_t*>(image.row(0));
  const std::size_t first =
      static_cast<std::size_t>(frame.y_offset) * stride + static_cast<std::size_t>(frame.x_offset) * 4;
  const bool decoded = inside && WebPDecodeRGBAInto(frame.fragment.bytes, frame.fragment.size, canvas + first,
                                                    stride * static_cast<std::size_t>(image.height()) - first,
                                                    static_cast<int>(stride)) != nullptr;
  WebPDemuxReleaseIterator(&frame);
  if (!decoded)
    return Error{ErrorKind::kCorruptInput, "not a readable WebP animation (its first frame is broken)"};
  premultiply_into(canvas, image);  // in place, as for a still image
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
