// GIF decoding (gif_decode.h), through giflib's record-level API: only the records up to the first
// image and the descriptor of the next one are read, so an animation of many frames costs no more than its
// first.
#include "gif_decode.h"

#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "curvescan/raster/limits.h"

namespace curvescan::svg::detail {
namespace {

struct Reader {
  std::span<const std::uint8_t> bytes;
  std::size_t offset = 0;
};

int read_bytes(GifFileType* gif, GifByteType* out, int wanted) {
  auto* reader = static_cast<Reader*>(gif->UserData);
  const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(std::max(wanted, 0)),
                                                  reader->bytes.size() - reader->offset);
  std::memcpy(out, reader->bytes.data() + reader->offset, count);
  reader->offset += count;
  return static_cast<int>(count);
}

struct GifCloser {
  void operator()(GifFileType* gif) const noexcept {
    int ignored = 0;
    DGifCloseFile(gif, &ignored);
  }
};

Error corrupt(const GifFileType* gif, const char* what) {
  const char* reason = gif ? GifErrorString(gif->Error) : nullptr;
  return Error{ErrorKind::kCorruptInput,
               std::string("not a readable GIF image (") + (reason ? reason : what) + ")"};
}

std::int64_t little_endian_16(const std::uint8_t* p) noexcept {
  return p[0] | (p[1] << 8);
}

// Whether another image follows the one just read: the records up to the next image descriptor or the
// trailer, skipping extensions. A file broken after its first image is not animated: the first image
// stands, as a browser shows what it could decode.
bool another_image_follows(GifFileType* gif) {
  while (true) {
    GifRecordType record = UNDEFINED_RECORD_TYPE;
    if (DGifGetRecordType(gif, &record) == GIF_ERROR) return false;
    if (record == IMAGE_DESC_RECORD_TYPE) return true;
    if (record == TERMINATE_RECORD_TYPE) return false;
    if (record == EXTENSION_RECORD_TYPE) {
      int code = 0;
      GifByteType* block = nullptr;
      if (DGifGetExtension(gif, &code, &block) == GIF_ERROR) return false;
      while (block != nullptr) {
        if (DGifGetExtensionNext(gif, &block) == GIF_ERROR) return false;
      }
    }
  }
}

}  // namespace

bool is_gif(std::span<const std::uint8_t> bytes) noexcept {
  return bytes.size() >= 6 &&
         (std::memcmp(bytes.data(), "GIF87a", 6) == 0 || std::memcmp(bytes.data(), "GIF89a", 6) == 0);
}

std::optional<std::pair<std::int64_t, std::int64_t>> gif_dimensions(
    std::span<const std::uint8_t> bytes) noexcept {
  // The logical screen descriptor follows the 6-byte signature: width and height, 16 bits little-endian.
  if (bytes.size() < 13 || !is_gif(bytes)) return std::nullopt;
  return std::pair{little_endian_16(bytes.data() + 6), little_endian_16(bytes.data() + 8)};
}

Result<Image> decode_gif(std::span<const std::uint8_t> bytes, std::int64_t max_pixels, bool* animated) {
  const std::optional<std::pair<std::int64_t, std::int64_t>> screen = gif_dimensions(bytes);
  if (!screen) return Error{ErrorKind::kCorruptInput, "not a readable GIF image (no header)"};
  const auto [width, height] = *screen;
  if (width < 1 || height < 1) return Error{ErrorKind::kCorruptInput, "a GIF image of no pixels"};
  if (width > kMaxImageDimension || height > kMaxImageDimension || width * height > max_pixels) {
    return Error{ErrorKind::kLimitExceeded, "a GIF image of " + std::to_string(width) + " x " +
                                                std::to_string(height) + " pixels is beyond the pixel limit"};
  }
  Reader reader{bytes};
  int error = 0;
  std::unique_ptr<GifFileType, GifCloser> gif(DGifOpen(&reader, read_bytes, &error));
  if (!gif)
    return Error{ErrorKind::kCorruptInput, std::string("not a readable GIF image (") +
                                               (GifErrorString(error) ? GifErrorString(error) : "") + ")"};
  int transparent = NO_TRANSPARENT_COLOR;
  while (true) {
    GifRecordType record = UNDEFINED_RECORD_TYPE;
    if (DGifGetRecordType(gif.get(), &record) == GIF_ERROR) return corrupt(gif.get(), "a broken record");
    if (record == TERMINATE_RECORD_TYPE) return corrupt(nullptr, "no image in the file");
    if (record == EXTENSION_RECORD_TYPE) {
      int code = 0;
      GifByteType* block = nullptr;
      if (DGifGetExtension(gif.get(), &code, &block) == GIF_ERROR)
        return corrupt(gif.get(), "a broken extension");
      if (code == GRAPHICS_EXT_FUNC_CODE && block != nullptr) {
        GraphicsControlBlock control{};
        if (DGifExtensionToGCB(block[0], block + 1, &control) == GIF_OK)
          transparent = control.TransparentColor;
      }
      while (block != nullptr) {
        if (DGifGetExtensionNext(gif.get(), &block) == GIF_ERROR)
          return corrupt(gif.get(), "a broken extension");
      }
      continue;
    }
    if (record != IMAGE_DESC_RECORD_TYPE) continue;
    if (DGifGetImageDesc(gif.get()) == GIF_ERROR) return corrupt(gif.get(), "a broken image descriptor");
    const GifImageDesc& frame = gif->Image;
    const ColorMapObject* colours = frame.ColorMap ? frame.ColorMap : gif->SColorMap;
    if (colours == nullptr) return corrupt(nullptr, "no colour table");
    if (frame.Width < 1 || frame.Height < 1) return corrupt(nullptr, "an image of no pixels");
    // Every row of a frame is decoded, even the part outside the screen, so the frame's own area is
    // bounded too: a 1 x 1 screen must not hide a 65535 x 65535 frame (4·10⁹ pixels of LZW work).
    if (std::int64_t{frame.Width} * frame.Height > max_pixels) {
      return Error{ErrorKind::kLimitExceeded, "a GIF frame of " + std::to_string(frame.Width) + " x " +
                                                  std::to_string(frame.Height) +
                                                  " pixels is beyond the pixel limit"};
    }
    Image image(static_cast<int>(width), static_cast<int>(height));  // transparent black
    std::vector<GifPixelType> line(static_cast<std::size_t>(frame.Width));
    // Interlaced rows come in four passes (GIF89a appendix E): every 8th from 0, every 8th from 4, every
    // 4th from 2, every 2nd from 1.
    static constexpr int kStart[] = {0, 4, 2, 1}, kStep[] = {8, 8, 4, 2};
    const int passes = frame.Interlace ? 4 : 1;
    for (int pass = 0; pass < passes; ++pass) {
      const int start = frame.Interlace ? kStart[pass] : 0, step = frame.Interlace ? kStep[pass] : 1;
      for (int row = start; row < frame.Height; row += step) {
        const std::int64_t y = std::int64_t{frame.Top} + row;
        // The part of a frame below the logical screen is not shown: rows in order end there, unread (an
        // interlaced frame's rows must all be read, its later passes come back to rows on the screen).
        if (y >= height && !frame.Interlace) break;
        if (DGifGetLine(gif.get(), line.data(), frame.Width) == GIF_ERROR)
          return corrupt(gif.get(), "truncated image data");
        if (y >= height) continue;
        Rgba8* out = image.row(static_cast<int>(y));
        for (int column = 0; column < frame.Width; ++column) {
          const std::int64_t x = std::int64_t{frame.Left} + column;
          const int index = line[static_cast<std::size_t>(column)];
          if (x >= width || index == transparent || index >= colours->ColorCount) continue;
          const GifColorType& c = colours->Colors[index];
          out[x] = Rgba8{c.Red, c.Green, c.Blue, 255};
        }
      }
    }
    if (animated != nullptr) *animated = another_image_follows(gif.get());
    return image;
  }
}

}  // namespace curvescan::svg::detail
