// PNG input through libpng, from memory and from files (contract in png_io.h).
//
// Error handling. libpng reports errors by calling an error function that must not return; we install
// one that copies the message into a fixed buffer and png_longjmp()s back to the setjmp() of the phase in
// progress. A longjmp is only defined in C++ if a throw in its place would run no non-trivial destructor
// ([support.signal]/[csetjmp.syn]): so every function that calls setjmp() below (read_header,
// read_pixels) holds only trivially destructible locals, and every C++ object (the Image,
// the row pointers, the file bytes) lives in the caller's frame, outside the jump. Values a phase
// produces are written through pointers into a job struct, never into its own locals, so no `volatile`
// is needed.
//
// Reading. read_png reads the whole file into memory first, at most its size bound plus one byte (so a
// FIFO or a device such as /dev/zero ends at the bound instead of filling memory), and decode_png feeds
// libpng from memory by a read callback; a request past the end is reported as truncation with the
// offset, a clearer message than libpng's "Read Error". Dimensions are checked against limits.h after the
// header and before any pixel memory is allocated. The transforms make any PNG 8-bit RGBA: palette and
// low-bit grey expanded and tRNS turned into alpha (png_set_expand), 16-bit scaled to 8 with rounding
// (png_set_scale_16: v·255/65535 to nearest, where png_set_strip_16 would truncate to the high byte), grey to
// RGB, an opaque alpha added when the file has none, and Adam7 deinterlaced by png_set_interlace_handling. No
// gamma correction is applied (as Cairo's reader does not), so samples come out exactly as stored.
//
// Writing: png_encode.cpp.
#include "curvescan/raster/png_io.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/file_io.h"
#include "curvescan/raster/pixel_format.h"
#include "quoted_path.h"

namespace curvescan {
namespace {

// ---- shared: libpng error and warning callbacks ---------------------------------------------------------

// libpng messages are short (its own buffers are 64..200 bytes); a longer one is cut, never overflowed.
struct PngErrorState {
  char message[256] = {};
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message != nullptr ? message : "unknown error");
  png_longjmp(png, 1);
}

// Warnings (an ancillary chunk with a bad CRC, an unknown sRGB profile) do not stop a read: the pixels are
// still good, and printing to stderr is the CLI's business, not the library's.
void on_png_warning(png_structp /*png*/, png_const_charp /*message*/) {}

using detail::quoted;

// ---- reading -------------------------------------------------------------------------------------------

struct MemoryReader {
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
  std::size_t offset = 0;
};

void read_from_memory(png_structp png, png_bytep out, png_size_t count) {
  auto* reader = static_cast<MemoryReader*>(png_get_io_ptr(png));
  if (count > reader->size - reader->offset) {
    char message[128];
    std::snprintf(message, sizeof message, "the file is truncated: it ends after %zu bytes, inside a chunk",
                  reader->size);
    png_error(png, message);
  }
  std::memcpy(out, reader->data + reader->offset, count);
  reader->offset += count;
}

// Everything one read needs, owned by read_png's frame (see the essay on longjmp above).
struct ReadJob {
  png_structp png = nullptr;
  png_infop info = nullptr;
  MemoryReader reader;
  PngErrorState error;
  png_uint_32 width = 0;
  png_uint_32 height = 0;
};

// Phase 1: signature, header, transforms. False on a libpng error (message in job->error).
bool read_header(ReadJob* job) {
  if (setjmp(png_jmpbuf(job->png))) return false;
  png_set_read_fn(job->png, &job->reader, read_from_memory);
  // Our own limit check (limits.h) gives the clearer message, so libpng's default 1e6 x 1e6 user limit is
  // lifted to the PNG format's own maximum; no memory depends on the dimensions before we check them.
  png_set_user_limits(job->png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
  // The text and profile chunks libpng inflates (zTXt, iTXt, iCCP) may expand to at most this much; past
  // it libpng drops the chunk with a warning. The declared chunk lengths were checked against the file by
  // find_overlong_chunk before libpng saw them.
  constexpr png_alloc_size_t kMaxInflatedChunkBytes = png_alloc_size_t{8} << 20;
  png_set_chunk_malloc_max(job->png, kMaxInflatedChunkBytes);
  png_read_info(job->png, job->info);
  job->width = png_get_image_width(job->png, job->info);
  job->height = png_get_image_height(job->png, job->info);
  if (!image_size_within_limits(job->width, job->height)) return true;  // the caller refuses it

  png_set_expand(job->png);
  png_set_scale_16(job->png);
  png_set_gray_to_rgb(job->png);
  png_set_add_alpha(job->png, 0xff, PNG_FILLER_AFTER);  // a no-op when the image already has alpha
  png_set_interlace_handling(job->png);
  png_read_update_info(job->png, job->info);
  if (png_get_rowbytes(job->png, job->info) != std::size_t{job->width} * 4u) {
    png_error(job->png, "libpng could not convert the image to 8-bit RGBA");
  }
  return true;
}

// Phase 2: decode into `rows` (width * 4 bytes each) and read to IEND, so a file cut after its last IDAT is
// reported as truncated too. False on a libpng error.
bool read_pixels(ReadJob* job, png_bytepp rows) {
  if (setjmp(png_jmpbuf(job->png))) return false;
  png_read_image(job->png, rows);
  png_read_end(job->png, nullptr);
  return true;
}

// libpng allocates a chunk's declared length before it reads the chunk's data, and its own check of that
// length only warns (a "benign error"): an 85-byte file declaring a 1.9 GB tEXt chunk allocated 1.9 GB
// (fuzz/regressions/png_read/). A chunk longer than the rest of the file would fail the read anyway (libpng
// reads through IEND), so walking the chunk headers first and refusing such a file changes no outcome,
// only the memory spent and the message. The offset of the first chunk (length, type, data, CRC; PNG
// specification 5.3) that runs past the end, or nullopt; the walk stops at IEND.
std::optional<std::size_t> find_overlong_chunk(std::span<const std::uint8_t> data) {
  constexpr std::size_t kSignatureSize = 8, kHeaderSize = 8, kCrcSize = 4;
  std::size_t offset = kSignatureSize;
  while (data.size() - offset >= kHeaderSize) {
    const std::uint8_t* header = data.data() + offset;
    const std::size_t length = std::size_t{header[0]} << 24 | std::size_t{header[1]} << 16 |
                               std::size_t{header[2]} << 8 | std::size_t{header[3]};
    if (length > data.size() - offset - kHeaderSize) return offset;
    if (std::memcmp(header + 4, "IEND", 4) == 0) break;
    offset += kHeaderSize + length + std::min(kCrcSize, data.size() - offset - kHeaderSize - length);
  }
  return std::nullopt;
}

}  // namespace

Result<Image> decode_png(std::span<const std::uint8_t> data, std::int64_t max_pixels) {
  max_pixels = std::min(max_pixels, kMaxImagePixels);
  if (data.empty()) return Error{ErrorKind::kCorruptInput, "the file is empty"};
  constexpr std::size_t kSignatureSize = 8;
  if (data.size() < kSignatureSize || png_sig_cmp(data.data(), 0, kSignatureSize) != 0) {
    return Error{ErrorKind::kCorruptInput, "not a PNG file (the 8-byte PNG signature is missing)"};
  }

  if (const std::optional<std::size_t> offset = find_overlong_chunk(data)) {
    return Error{ErrorKind::kCorruptInput, "the file is truncated: the chunk at offset " +
                                               std::to_string(*offset) + " is longer than the rest of the file"};
  }

  ReadJob job;
  job.reader = {data.data(), data.size(), 0};
  job.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &job.error, on_png_error, on_png_warning);
  if (job.png != nullptr) job.info = png_create_info_struct(job.png);
  struct Cleanup {
    ReadJob& job;
    ~Cleanup() { png_destroy_read_struct(&job.png, job.info != nullptr ? &job.info : nullptr, nullptr); }
  } cleanup{job};
  if (job.info == nullptr) return Error{ErrorKind::kIoError, "out of memory"};

  const auto corrupt = [&] { return Error{ErrorKind::kCorruptInput, job.error.message}; };
  if (!read_header(&job)) return corrupt();
  if (!image_size_within_limits(job.width, job.height) ||
      std::int64_t{job.width} * std::int64_t{job.height} > max_pixels) {
    return Error{ErrorKind::kLimitExceeded,
                 "its " + std::to_string(job.width) + " x " + std::to_string(job.height) +
                     " pixels exceed curvescan's limit (at most " + std::to_string(kMaxImageDimension) +
                     " per side and " + std::to_string(max_pixels) + " pixels in all)"};
  }

  // Decode straight into the Image's storage: Rgba8 is four bytes R, G, B, A, the layout libpng produces.
  static_assert(sizeof(Rgba8) == 4 && alignof(Rgba8) == 1);
  Image image(static_cast<int>(job.width), static_cast<int>(job.height));
  std::vector<png_bytep> rows(job.height);
  for (int y = 0; y < image.height(); ++y) {
    rows[static_cast<std::size_t>(y)] = reinterpret_cast<png_bytep>(image.row(y));  // object bytes
  }
  if (!read_pixels(&job, rows.data())) return corrupt();

  for (Rgba8& pixel : image.pixels()) pixel = premultiply({pixel.r, pixel.g, pixel.b, pixel.a});
  return image;
}

Result<Image> read_png(const std::filesystem::path& path, std::size_t max_file_bytes) {
  const Result<std::vector<std::uint8_t>> bytes =
      read_file_bounded(path, ReadBound{max_file_bytes, "the PNG file size limit"});
  if (!bytes) return bytes.error();
  Result<Image> image = decode_png(*bytes);
  if (!image) return Error{image.error().kind, "cannot read " + quoted(path) + ": " + image.error().message};
  return image;
}

}  // namespace curvescan
