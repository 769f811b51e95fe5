// Loading and decoding the pixels of <image> and <feImage> files within the render's memory budget
// (image_loading.h).
#include "image_loading.h"

#include <algorithm>
#include <string>

#include "curvescan/raster/png_io.h"
#include "curvescan/svg/gzip.h"
#include "gif_decode.h"
#include "image_dimensions.h"
#include "jpeg_decode.h"
#include "webp_decode.h"

namespace curvescan::svg::detail {

ImageBytes load_image_bytes(std::string_view href,
                            const std::optional<std::filesystem::path>& resource_directory,
                            std::int64_t memory_left) {
  const std::size_t left = memory_left > 0 ? static_cast<std::size_t>(memory_left) : 0;
  ImageBytes source =
      left < kMaxPngFileBytes
          ? load_image_source(href, resource_directory, left,
                              "the memory the render has left (raise --max-memory)")
          : load_image_source(href, resource_directory, kMaxPngFileBytes, "the image file size limit");
  const std::string_view bytes(reinterpret_cast<const char*>(source.bytes.data()), source.bytes.size());
  if (source.refused.empty() && is_gzip(bytes)) {
    const std::size_t bound = std::min(left - std::min(left, source.bytes.size()), kMaxPngFileBytes);
    const Result<std::string> inflated = gunzip(bytes, bound);
    if (inflated) {
      source.bytes.assign(inflated->begin(), inflated->end());
    } else {
      source.bytes.clear();
      source.refused = inflated.error().message;
    }
  }
  return source;
}

Result<Image> decode_image_within_budget(const std::vector<std::uint8_t>& bytes, ImageFormat format,
                                         std::int64_t memory_left, std::int64_t held, std::int64_t max_pixels,
                                         bool* animated) {
  if (animated != nullptr) *animated = false;
  if (const std::optional<ImageDimensions> size = declared_dimensions(bytes, format)) {
    const std::int64_t left = memory_left - held;
    const std::int64_t pixel_bytes = image_memory_bytes(size->width, size->height);
    if (pixel_bytes > left) {
      const auto mib = [](std::int64_t n) {
        return std::to_string((std::max<std::int64_t>(n, 0) + (1 << 20) - 1) >> 20);
      };
      return Error{ErrorKind::kLimitExceeded,
                   "its " + std::to_string(size->width) + " x " + std::to_string(size->height) +
                       " pixels would take " + mib(pixel_bytes) + " MiB, more than the " + mib(left) +
                       " MiB the render has left under its memory limit (raise --max-memory)"};
    }
  }
  switch (format) {
    case ImageFormat::kPng:
      return decode_png(bytes, max_pixels);
    case ImageFormat::kGif:
      return decode_gif(bytes, max_pixels, animated);
    case ImageFormat::kWebp:
      return decode_webp(bytes, max_pixels, animated);
    default:
      return decode_jpeg(bytes, max_pixels);
  }
}

}  // namespace curvescan::svg::detail
