// PNG input and output through libpng, in memory and in files (contract in png_io.h).
//
// Error handling. libpng reports errors by calling an error function that must not return; we install
// one that copies the message into a fixed buffer and png_longjmp()s back to the setjmp() of the phase in
// progress. A longjmp is only defined in C++ if a throw in its place would run no non-trivial destructor
// ([support.signal]/[csetjmp.syn]): so every function that calls setjmp() below (read_header,
// read_pixels, write_pixels) holds only trivially destructible locals, and every C++ object (the Image,
// the row buffers, the file bytes, the encoded bytes) lives in the caller's frame, outside the jump; the
// memory writer's callback catches its own std::bad_alloc and calls png_error only after the handler ended. Values a phase
// produces are written through pointers into a job struct, never into its own locals, so no `volatile`
// is needed.
//
// Reading. read_png reads the whole file into memory first, at most its size bound plus one byte (so a
// FIFO or a device such as /dev/zero ends at the bound instead of filling memory), and decode_png feeds
// libpng from memory by a read callback; a request past the end is reported as truncation with the
// offset, a clearer message than libpng's "Read Error". Dimensions are checked against limits.h after the header and before any pixel memory is
// allocated. The transforms make any PNG 8-bit RGBA: palette and low-bit grey expanded and tRNS turned
// into alpha (png_set_expand), 16-bit scaled to 8 with rounding (png_set_scale_16: v·255/65535 to
// nearest, where png_set_strip_16 would truncate to the high byte), grey to RGB, an opaque alpha added
// when the file has none, and Adam7 deinterlaced by png_set_interlace_handling. No gamma correction is
// applied (as Cairo's reader does not), so samples come out exactly as stored.
//
// Writing. Pixels are unpremultiplied row by row (pixel_format.h, rounding to nearest) and handed to a
// write callback that appends to a byte vector (encode_png); write_png hands the finished bytes to
// write_output_file (file_io.h), which replaces a regular file atomically and writes devices and
// pipes through, so a failed encode touches no file at all. Row filters: libpng's default tries all five
// (PNG specification 9.2) on every row and keeps the one with the smallest sum of absolute values (the
// heuristic of the specification's 12.8); that was three quarters of the CPU time of a batch of small
// icons. Only None and Up are tried here (None suits the flat colours and transparent areas of rendered
// vector art, Up the vertical coherence of gradients): 300 Adwaita icons at 256 px took 0.54 s of CPU
// instead of 0.78 s, their files 6 % larger; 200 renders of resvg's test suite (gradients, filters,
// text) 0.31 s instead of 0.47 s, 1.6 % larger. The filters are lossless: the pixels do not change.
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

// ---- writing -------------------------------------------------------------------------------------------

void flush_nothing(png_structp /*png*/) {}  // the bytes are in memory: nothing to flush

// encode_png's destination. The callback runs inside libpng, so a std::bad_alloc must not cross it: it
// is caught, and png_error is called after the handler has ended.
struct MemoryWriter {
  std::vector<std::uint8_t>* bytes = nullptr;
  bool out_of_memory = false;
};

void write_to_memory(png_structp png, png_bytep data, png_size_t count) {
  auto* writer = static_cast<MemoryWriter*>(png_get_io_ptr(png));
  try {
    writer->bytes->insert(writer->bytes->end(), data, data + count);
  } catch (const std::bad_alloc&) {
    writer->out_of_memory = true;
  }
  if (writer->out_of_memory) png_error(png, "out of memory");
}

struct WriteJob {
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngErrorState error;
  MemoryWriter* io = nullptr;
};

// Writes `image` as straight RGBA8, unpremultiplying each row into `row_buffer` (width * 4 bytes).
bool write_pixels(WriteJob* job, const Image* image, std::uint8_t* row_buffer) {
  if (setjmp(png_jmpbuf(job->png))) return false;
  png_set_write_fn(job->png, job->io, write_to_memory, flush_nothing);
  png_set_IHDR(job->png, job->info, static_cast<png_uint_32>(image->width()),
               static_cast<png_uint_32>(image->height()), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(job->png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE | PNG_FILTER_UP);
  png_write_info(job->png, job->info);
  for (int y = 0; y < image->height(); ++y) {
    const Rgba8* source = image->row(y);
    for (int x = 0; x < image->width(); ++x) {
      const StraightRgba8 straight = unpremultiply(source[x]);
      std::uint8_t* out = row_buffer + 4 * static_cast<std::size_t>(x);
      out[0] = straight.r;
      out[1] = straight.g;
      out[2] = straight.b;
      out[3] = straight.a;
    }
    png_write_row(job->png, row_buffer);
  }
  png_write_end(job->png, nullptr);
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

Result<std::vector<std::uint8_t>> encode_png(const Image& image) {
  if (image.empty()) return Error{ErrorKind::kInvalidArgument, "cannot encode a PNG: the image has no pixels"};
  if (!image_size_within_limits(image.width(), image.height())) {
    return Error{ErrorKind::kLimitExceeded, "cannot encode a PNG: the image exceeds the size limit"};
  }
  std::vector<std::uint8_t> bytes;
  MemoryWriter memory{&bytes};
  WriteJob job;
  job.io = &memory;
  job.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job.error, on_png_error, on_png_warning);
  if (job.png != nullptr) job.info = png_create_info_struct(job.png);
  std::vector<std::uint8_t> row_buffer(4 * static_cast<std::size_t>(image.width()));
  const bool created = job.info != nullptr;
  const bool ok = created && write_pixels(&job, &image, row_buffer.data());
  png_destroy_write_struct(&job.png, created ? &job.info : nullptr);  // sets job.info to null
  if (!ok) {
    return Error{ErrorKind::kIoError, std::string("cannot encode a PNG: ") +
                                          (!created || memory.out_of_memory
                                               ? "out of memory"
                                               : std::string("libpng: ") + job.error.message)};
  }
  return bytes;
}

Status write_png(const Image& image, const std::filesystem::path& path) {
  const Result<std::vector<std::uint8_t>> bytes = encode_png(image);
  if (!bytes) {
    std::string reason = bytes.error().message;
    if (reason.rfind("cannot encode a PNG: ", 0) == 0) reason.erase(0, sizeof "cannot encode a PNG: " - 1);
    return Error{bytes.error().kind, "cannot write " + quoted(path) + ": " + reason};
  }
  return write_output_file(path, std::span<const std::uint8_t>(*bytes));
}

}  // namespace curvescan
