// JPEG decoding (jpeg_decode.h). libjpeg reports errors through error_exit, which must not return: it
// longjmps back to the setjmp of the phase that called libjpeg (C++ [csetjmp.syn]: the jump may skip no
// destructor, hence the phases below own no C++ object).
#include "jpeg_decode.h"

#include <csetjmp>
#include <cstdio>  // jpeglib.h uses FILE and size_t without including their headers
#include <string>
#include <vector>

// clang-format off
#include <jpeglib.h>
// clang-format on

#include "curvescan/raster/limits.h"

namespace curvescan::svg::detail {
namespace {

struct ErrorManager {
  jpeg_error_mgr base;  // first member: libjpeg hands back a pointer to it
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void error_exit(j_common_ptr info) {
  auto* manager = reinterpret_cast<ErrorManager*>(info->err);
  manager->base.format_message(info, manager->message);
  std::longjmp(manager->jump, 1);
}

void silent(j_common_ptr, int) {}  // warnings (a corrupt but decodable stream) are not errors here

// The two phases that call into libjpeg, each with its own setjmp and no C++ object of its own, so a
// longjmp skips nothing (the buffers are the caller's, allocated between the phases). False on error.
bool read_header(jpeg_decompress_struct& info, ErrorManager& errors, std::span<const std::uint8_t> bytes) {
  if (setjmp(errors.jump) != 0) return false;
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
  info.out_color_space = cmyk ? JCS_CMYK : JCS_RGB;
  jpeg_calc_output_dimensions(&info);
  return true;
}

bool read_pixels(jpeg_decompress_struct& info, ErrorManager& errors, Image& image, JSAMPLE* row) {
  if (setjmp(errors.jump) != 0) return false;
  jpeg_start_decompress(&info);
  const bool cmyk = info.out_color_space == JCS_CMYK;
  while (info.output_scanline < info.output_height) {
    JSAMPROW rows[] = {row};
    Rgba8* out = image.row(static_cast<int>(info.output_scanline));
    jpeg_read_scanlines(&info, rows, 1);
    for (unsigned x = 0; x < info.output_width; ++x) {
      const JSAMPLE* p = row + std::size_t{x} * static_cast<std::size_t>(info.output_components);
      if (cmyk) {
        // Adobe writes CMYK inverted (the value is 255 - ink), so the colour is value·K/255.
        const unsigned k = p[3];
        out[x] = Rgba8{static_cast<std::uint8_t>(p[0] * k / 255), static_cast<std::uint8_t>(p[1] * k / 255),
                       static_cast<std::uint8_t>(p[2] * k / 255), 255};
      } else {
        out[x] = Rgba8{p[0], p[1], p[2], 255};
      }
    }
  }
  jpeg_finish_decompress(&info);
  return true;
}

void install_errors(jpeg_decompress_struct& info, ErrorManager& errors) {
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = error_exit;
  errors.base.emit_message = silent;
}

}  // namespace

std::optional<std::pair<std::int64_t, std::int64_t>> jpeg_dimensions(std::span<const std::uint8_t> bytes) {
  jpeg_decompress_struct info{};
  ErrorManager errors{};
  install_errors(info, errors);
  const bool read = read_header(info, errors, bytes);
  const std::pair<std::int64_t, std::int64_t> size{info.output_width, info.output_height};
  jpeg_destroy_decompress(&info);
  if (!read) return std::nullopt;
  return size;
}

Result<Image> decode_jpeg(std::span<const std::uint8_t> bytes, std::int64_t max_pixels) {
  jpeg_decompress_struct info{};
  ErrorManager errors{};
  install_errors(info, errors);
  const auto fail = [&] {
    jpeg_destroy_decompress(&info);
    return Error{ErrorKind::kCorruptInput, std::string("JPEG: ") + errors.message};
  };
  if (!read_header(info, errors, bytes)) return fail();
  const std::int64_t pixels = std::int64_t{info.output_width} * info.output_height;
  if (info.output_width > static_cast<unsigned>(kMaxImageDimension) ||
      info.output_height > static_cast<unsigned>(kMaxImageDimension) || pixels > max_pixels) {
    jpeg_destroy_decompress(&info);
    return Error{ErrorKind::kLimitExceeded, "JPEG: the image is larger than the pixel limit"};
  }
  Image image(static_cast<int>(info.output_width), static_cast<int>(info.output_height));
  // Room for 4 components, the most libjpeg gives for the colour spaces asked for above.
  std::vector<JSAMPLE> row(std::size_t{info.output_width} * 4);
  if (!read_pixels(info, errors, image, row.data())) return fail();
  jpeg_destroy_decompress(&info);
  return image;
}

}  // namespace curvescan::svg::detail
