// Font: FreeType face loading and glyph outlines through FT_Outline_Decompose.
//
// FT_Outline_Decompose turns FreeType's outline (TrueType on/off-curve points, or CFF cubic control
// points) into move/line/conic/cubic callbacks; a TrueType "conic" is an ordinary quadratic Bézier
// (FreeType docs, FT_Outline_ConicToFunc), so the callbacks map one to one onto PathBuilder's move_to,
// line_to, quad_to and cubic_to. Each contour is closed explicitly: FreeType's own renderers fill
// contours as closed, and Path keeps an open contour open until a fill closes it implicitly, so closing
// makes the Path say what the font means.
#include "curvescan/text/font.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <utility>

#include "curvescan/raster/file_io.h"
#include "font_face_p.h"  // ft2build.h first: FreeType's header macros below need it
#include FT_ADVANCES_H
#include FT_FONT_FORMATS_H
#include FT_MULTIPLE_MASTERS_H
#include FT_TRUETYPE_TABLES_H
#include FT_OUTLINE_H

namespace curvescan {

Font::Impl::~Impl() {
  if (hb_font != nullptr) hb_font_destroy(hb_font);
  if (hb_face != nullptr) hb_face_destroy(hb_face);
  if (blob != nullptr) hb_blob_destroy(blob);
  if (face != nullptr) FT_Done_Face(face);
  if (library != nullptr) FT_Done_FreeType(library);
}

namespace {

// Outline loading flags: no hinting (the outline is the designer's, at any size), no embedded bitmaps
// (we want outlines even where the font carries bitmap strikes).
constexpr FT_Int32 kUnscaledLoadFlags = FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP;
constexpr FT_Int32 kScaledLoadFlags = FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP;

OutlineFormat outline_format_of(FT_Face face) {
  const char* format = FT_Get_Font_Format(face);
  if (format == nullptr) return OutlineFormat::kOther;
  if (std::strcmp(format, "TrueType") == 0) return OutlineFormat::kTrueType;
  if (std::strcmp(format, "CFF") == 0) return OutlineFormat::kCff;
  return OutlineFormat::kOther;
}

// The decomposition callbacks' shared state: where points go and how they are mapped.
struct DecomposeTarget {
  PathBuilder* builder = nullptr;
  Affine transform;
  double unit = 1.0;  // outline coordinate -> source unit (1 for font units, 1/64 for 26.6 pixels)
  bool contour_open = false;

  [[nodiscard]] Point map(const FT_Vector* v) const noexcept {
    return transform.apply(Point{static_cast<double>(v->x) * unit, static_cast<double>(v->y) * unit});
  }
};

DecomposeTarget& target_of(void* user) {
  return *static_cast<DecomposeTarget*>(user);
}

int on_move(const FT_Vector* to, void* user) {
  DecomposeTarget& t = target_of(user);
  if (t.contour_open) t.builder->close();
  t.builder->move_to(t.map(to));
  t.contour_open = true;
  return 0;
}
int on_line(const FT_Vector* to, void* user) {
  DecomposeTarget& t = target_of(user);
  t.builder->line_to(t.map(to));
  return 0;
}
int on_conic(const FT_Vector* control, const FT_Vector* to, void* user) {
  DecomposeTarget& t = target_of(user);
  t.builder->quad_to(t.map(control), t.map(to));
  return 0;
}
int on_cubic(const FT_Vector* control1, const FT_Vector* control2, const FT_Vector* to, void* user) {
  DecomposeTarget& t = target_of(user);
  t.builder->cubic_to(t.map(control1), t.map(control2), t.map(to));
  return 0;
}

Status decompose(const FT_Outline& outline, DecomposeTarget& target, const std::string& what) {
  const FT_Outline_Funcs funcs{on_move, on_line, on_conic, on_cubic, 0, 0};
  // FT_Outline_Decompose only reads the outline; its parameter is non-const for historical reasons.
  FT_Outline copy = outline;
  if (FT_Outline_Decompose(&copy, &funcs, &target) != 0) {
    return Error{ErrorKind::kCorruptInput, what + " has a malformed outline"};
  }
  if (target.contour_open) target.builder->close();
  target.contour_open = false;
  return Status::ok();
}

std::string glyph_name(const Font::Impl& impl, GlyphId glyph) {
  return "glyph " + std::to_string(glyph) + " of " + impl.source_name;
}

Status check_glyph(const Font::Impl& impl, GlyphId glyph) {
  if (glyph >= static_cast<GlyphId>(impl.face->num_glyphs)) {
    return Error{ErrorKind::kInvalidArgument, "glyph index " + std::to_string(glyph) + " is outside " +
                                                  impl.source_name + " (" +
                                                  std::to_string(impl.face->num_glyphs) + " glyphs)"};
  }
  return Status::ok();
}

// What `status` is, for a message about a path that is not a regular file.
const char* file_type_name(const std::filesystem::file_status& status) {
  switch (status.type()) {
    case std::filesystem::file_type::directory:
      return "a directory";
    case std::filesystem::file_type::character:
      return "a character device";
    case std::filesystem::file_type::block:
      return "a block device";
    case std::filesystem::file_type::fifo:
      return "a FIFO";
    case std::filesystem::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

std::uint32_t read_be32(const std::vector<unsigned char>& bytes, std::size_t at) {
  return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 | std::uint32_t{bytes[at + 2]} << 8 |
         std::uint32_t{bytes[at + 3]};
}

// A cut or corrupt sfnt file (TrueType, OpenType, or face `face_index` of a collection): the table
// directory or a table it lists runs past the end of the file. FreeType reads some tables lazily (glyf,
// cmap), so such a file can open and then draw nothing or .notdef boxes without a word; checking the
// directory first names the problem. Layout from the OpenType specification, "Organization of an
// OpenType font": the sfnt version (4 bytes), numTables (2) at 4, 16-byte table records from 12 (tag,
// checksum, offset, length); a collection ("ttcf") has numFonts at 8 and their offsets from 12. Other
// formats (WOFF, Type 1) are left to FreeType. The message, or empty when the directory is whole.
std::string sfnt_truncation(const std::vector<unsigned char>& bytes, int face_index) {
  const std::size_t size = bytes.size();
  if (size < 4) return {};
  const std::uint32_t tag = read_be32(bytes, 0);
  constexpr std::uint32_t kCollection = 0x74746366;  // 'ttcf'
  std::size_t start = 0;
  if (tag == kCollection) {
    if (size < 12) return "the font collection header is cut short";
    const std::uint32_t fonts = read_be32(bytes, 8);
    if (face_index < 0 || static_cast<std::uint32_t>(face_index) >= fonts) return {};  // FreeType says
    const std::size_t record = 12 + 4 * static_cast<std::size_t>(face_index);
    if (record + 4 > size) return "the font collection header is cut short";
    start = read_be32(bytes, record);
    if (start + 4 > size) return "face " + std::to_string(face_index) + " starts past the end of the file";
  }
  const std::uint32_t version = read_be32(bytes, start);
  if (version != 0x00010000 && version != 0x4f54544f /* OTTO */ && version != 0x74727565 /* true */) return {};
  if (start + 12 > size) return "the table directory is cut short";
  const std::size_t tables = std::size_t{bytes[start + 4]} << 8 | bytes[start + 5];
  if (start + 12 + 16 * tables > size) return "the table directory is cut short";
  for (std::size_t i = 0; i < tables; ++i) {
    const std::size_t record = start + 12 + 16 * i;
    const std::uint64_t offset = read_be32(bytes, record + 8), length = read_be32(bytes, record + 12);
    if (offset + length > size) {
      return "its '" + std::string(reinterpret_cast<const char*>(bytes.data() + record), 4) + "' table (bytes " +
             std::to_string(offset) + " to " + std::to_string(offset + length) + ") runs past the end of the file";
    }
  }
  return {};
}

// The em size and vertical metrics in font units. FreeType fills them for a scalable face (and for an
// sbix one); for a bitmap-only face (CBDT without outlines) it leaves them 0 (FreeType docs, FT_FaceRec:
// "only relevant to scalable formats"), so they are read from "head" (unitsPerEm) and "hhea" (ascender,
// descender, lineGap), which the OpenType specification requires of every font.
void read_em_and_metrics(Font::Impl& impl) {
  const FT_Face face = impl.face;
  impl.units_per_em = face->units_per_EM;
  impl.ascender = face->ascender;
  impl.descender = face->descender;
  impl.line_height = face->height;
  if (impl.units_per_em > 0.0) return;
  const auto* head = static_cast<const TT_Header*>(FT_Get_Sfnt_Table(face, FT_SFNT_HEAD));
  const auto* hhea = static_cast<const TT_HoriHeader*>(FT_Get_Sfnt_Table(face, FT_SFNT_HHEA));
  if (head == nullptr || head->Units_Per_EM == 0) return;
  impl.units_per_em = head->Units_Per_EM;
  if (hhea != nullptr) {
    impl.ascender = hhea->Ascender;
    impl.descender = hhea->Descender;
    impl.line_height = static_cast<double>(hhea->Ascender) - hhea->Descender + hhea->Line_Gap;
  } else {  // no hhea: the em box, ascender 0.8 em (a common default)
    impl.ascender = 0.8 * impl.units_per_em;
    impl.descender = impl.ascender - impl.units_per_em;
    impl.line_height = impl.units_per_em;
  }
}

// Face `face_index` of the font file `bytes`, shared with every other Font of the same file (FreeType and
// HarfBuzz only read them); `name` for messages.
Result<std::unique_ptr<Font::Impl>> open_face(detail::FontFileBytes bytes, int face_index, const std::string& name) {
  if (bytes->size() > kMaxFontFileBytes) {
    return Error{ErrorKind::kLimitExceeded, "font '" + name + "' is larger than " +
                                                std::to_string(kMaxFontFileBytes >> 20) +
                                                " MiB, the font file size limit"};
  }
  if (const std::string cut = sfnt_truncation(*bytes, face_index); !cut.empty()) {
    return Error{ErrorKind::kCorruptInput, "'" + name + "' is truncated or corrupt: " + cut + " (" +
                                               std::to_string(bytes->size()) + " bytes)"};
  }
  auto impl = std::make_unique<Font::Impl>();
  impl->bytes = std::move(bytes);
  impl->source_name = name;
  if (FT_Init_FreeType(&impl->library) != 0) {
    return Error{ErrorKind::kIoError, "FreeType could not be initialised (out of memory?)"};
  }
  if (impl->bytes->empty() ||
      FT_New_Memory_Face(impl->library, impl->bytes->data(), static_cast<FT_Long>(impl->bytes->size()),
                         face_index, &impl->face) != 0) {
    impl->face = nullptr;
    return Error{ErrorKind::kCorruptInput, "'" + name + "' is not a font file FreeType can read (face " +
                                               std::to_string(face_index) + ")"};
  }
  impl->color_strikes = FT_HAS_COLOR(impl->face) && FT_HAS_FIXED_SIZES(impl->face);
  if (!FT_IS_SCALABLE(impl->face) && !impl->color_strikes) {
    return Error{ErrorKind::kUnsupported,
                 "'" + name + "' has no scalable outlines (a bitmap-only font without colour bitmaps)"};
  }
  read_em_and_metrics(*impl);
  if (!(impl->units_per_em > 0.0) || impl->face->num_glyphs <= 0) {
    return Error{ErrorKind::kCorruptInput, "'" + name + "' has no glyphs or a zero units-per-em"};
  }
  impl->family_name = impl->face->family_name != nullptr ? impl->face->family_name : "";
  impl->style_name = impl->face->style_name != nullptr ? impl->face->style_name : "";
  impl->format = outline_format_of(impl->face);
  impl->blob =
      hb_blob_create(reinterpret_cast<const char*>(impl->bytes->data()),
                     static_cast<unsigned>(impl->bytes->size()), HB_MEMORY_MODE_READONLY, nullptr, nullptr);
  impl->hb_face = hb_face_create(impl->blob, static_cast<unsigned>(face_index));
  impl->hb_font = hb_font_create(impl->hb_face);
  return impl;
}

}  // namespace

Result<Font> Font::open(const std::filesystem::path& file, int face_index) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (status.type() == std::filesystem::file_type::not_found)
    return Error{ErrorKind::kIoError, "font file '" + file.string() + "' does not exist"};
  if (error)
    return Error{ErrorKind::kIoError, "cannot read font file '" + file.string() + "': " + error.message()};
  if (!std::filesystem::is_regular_file(status)) {
    return Error{ErrorKind::kInvalidArgument,
                 "'" + file.string() + "' is not a font file: it is " + file_type_name(status)};
  }
  // The type was checked above for a clear message; the read checks it again on the opened file. A file
  // read before and unchanged since comes from the process's cache (font_file_cache_p.h).
  Result<detail::FontFileBytes> bytes = detail::read_font_file_cached(file, kMaxFontFileBytes);
  if (!bytes) return bytes.error();
  Result<std::unique_ptr<Impl>> impl = open_face(std::move(*bytes), face_index, file.string());
  if (!impl) return impl.error();
  return Font(std::move(*impl));
}

Result<Font> Font::from_bytes(std::vector<unsigned char> bytes, int face_index, const std::string& name) {
  Result<std::unique_ptr<Impl>> impl =
      open_face(std::make_shared<const std::vector<unsigned char>>(std::move(bytes)), face_index, name);
  if (!impl) return impl.error();
  return Font(std::move(*impl));
}

Font::Font(std::unique_ptr<Impl> impl) noexcept : impl_(std::move(impl)) {}
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;
Font::~Font() = default;

const std::string& Font::family_name() const noexcept {
  return impl_->family_name;
}
const std::string& Font::style_name() const noexcept {
  return impl_->style_name;
}
const std::string& Font::source_name() const noexcept {
  return impl_->source_name;
}
OutlineFormat Font::outline_format() const noexcept {
  return impl_->format;
}
std::size_t Font::glyph_count() const noexcept {
  return static_cast<std::size_t>(impl_->face->num_glyphs);
}

FontMetrics Font::metrics() const noexcept {
  const FT_Face face = impl_->face;
  FontMetrics metrics{impl_->units_per_em, impl_->ascender, impl_->descender, impl_->line_height};
  const double em = metrics.units_per_em;
  // The underline's centre. OpenType's post.underlinePosition is the top of the stroke (OpenType spec,
  // post table: "the suggested distance of the top of the underline from the baseline"; PostScript's
  // centre "is not used for historical reasons"), so the centre is half a thickness below it. FreeType's
  // face->underline_position is that centre, but halved in integers: an odd thickness puts it half a font
  // unit high. The table's own fields are read instead (with a variable font's MVAR deltas, which FreeType
  // applies to them); a face without sfnt tables (Type 1, whose FontInfo UnderlinePosition is the centre
  // already) keeps FreeType's values. A font without an underline (thickness 0) takes the fallbacks.
  double underline_thickness = face->underline_thickness;
  double underline_centre = face->underline_position;
  if (const auto* post = static_cast<const TT_Postscript*>(FT_Get_Sfnt_Table(face, FT_SFNT_POST));
      post != nullptr) {
    underline_thickness = post->underlineThickness;
    underline_centre = post->underlinePosition - 0.5 * underline_thickness;
  }
  metrics.underline_thickness = underline_thickness > 0 ? underline_thickness : em / 14.0;
  metrics.underline_position = underline_thickness > 0 ? underline_centre : -0.1 * em;
  metrics.x_height = 0.5 * em;
  metrics.strikeout_thickness = metrics.underline_thickness;
  metrics.strikeout_position = -1.0;  // set below
  metrics.subscript_offset = 0.2 * em;
  metrics.superscript_offset = 0.33 * em;
  const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(face, FT_SFNT_OS2));
  if (os2 != nullptr && os2->version != 0xFFFF) {
    if (os2->version >= 2 && os2->sxHeight > 0) metrics.x_height = os2->sxHeight;
    if (os2->yStrikeoutSize > 0) metrics.strikeout_thickness = os2->yStrikeoutSize;
    if (os2->yStrikeoutPosition > 0) metrics.strikeout_position = os2->yStrikeoutPosition;
    if (os2->ySubscriptYOffset > 0) metrics.subscript_offset = os2->ySubscriptYOffset;
    if (os2->ySuperscriptYOffset > 0) metrics.superscript_offset = os2->ySuperscriptYOffset;
  }
  if (metrics.strikeout_position < 0.0) {
    metrics.strikeout_position = 0.5 * metrics.x_height + 0.5 * metrics.strikeout_thickness;
  }
  return metrics;
}

namespace {

// The face's variation axes (FT_Get_MM_Var), freed with FT_Done_MM_Var; `var` is nullptr for a face
// without them.
struct VariationAxes {
  FT_Library library = nullptr;
  FT_MM_Var* var = nullptr;
  VariationAxes(FT_Library lib, FT_Face face) : library(lib) {
    if (!FT_HAS_MULTIPLE_MASTERS(face) || FT_Get_MM_Var(face, &var) != 0) var = nullptr;
  }
  VariationAxes(const VariationAxes&) = delete;
  VariationAxes& operator=(const VariationAxes&) = delete;
  ~VariationAxes() {
    if (var != nullptr) FT_Done_MM_Var(library, var);
  }
  [[nodiscard]] std::span<const FT_Var_Axis> axes() const noexcept {
    if (var == nullptr) return {};
    return {var->axis, var->num_axis};
  }
};

}  // namespace

bool Font::is_variable() const noexcept {
  return !VariationAxes(impl_->library, impl_->face).axes().empty();
}

bool Font::has_variation_axis(std::uint32_t tag) const noexcept {
  const VariationAxes axes(impl_->library, impl_->face);
  for (const FT_Var_Axis& axis : axes.axes())
    if (axis.tag == tag) return true;
  return false;
}

Status Font::set_variations(std::span<const FontVariation> variations) {
  const VariationAxes axes(impl_->library, impl_->face);
  const std::span<const FT_Var_Axis> list = axes.axes();
  if (list.empty()) return Status::ok();
  // FreeType's design coordinates are 16.16 fixed point, in axis order; HarfBuzz takes the same list as
  // floats (hb_font_set_var_coords_design), so both libraries see one point of the design space.
  std::vector<FT_Fixed> coordinates(list.size());
  if (FT_Get_Var_Design_Coordinates(impl_->face, static_cast<FT_UInt>(list.size()), coordinates.data()) != 0) {
    for (std::size_t i = 0; i < list.size(); ++i) coordinates[i] = list[i].def;
  }
  for (const FontVariation& variation : variations) {
    if (!std::isfinite(variation.value)) continue;
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (list[i].tag != variation.tag) continue;
      const double low = static_cast<double>(list[i].minimum) / 65536.0;
      const double high = static_cast<double>(list[i].maximum) / 65536.0;
      coordinates[i] = static_cast<FT_Fixed>(std::lround(std::clamp(variation.value, low, high) * 65536.0));
    }
  }
  if (FT_Set_Var_Design_Coordinates(impl_->face, static_cast<FT_UInt>(coordinates.size()), coordinates.data()) !=
      0) {
    return Error{ErrorKind::kCorruptInput, "'" + impl_->source_name + "' refuses its variation coordinates"};
  }
  std::vector<float> design(coordinates.size());
  for (std::size_t i = 0; i < coordinates.size(); ++i) design[i] = static_cast<float>(static_cast<double>(coordinates[i]) / 65536.0);
  hb_font_set_var_coords_design(impl_->hb_font, design.data(), static_cast<unsigned>(design.size()));
  // Shaped runs of the earlier coordinates no longer hold.
  impl_->shape_cache = detail::ShapeCache{};
  impl_->shaped.clear();
  return Status::ok();
}

GlyphId Font::glyph_for(char32_t character) const noexcept {
  return static_cast<GlyphId>(FT_Get_Char_Index(impl_->face, static_cast<FT_ULong>(character)));
}

double Font::advance(GlyphId glyph) const noexcept {
  FT_Fixed value = 0;
  // FreeType reads "hmtx" for a face without outlines (colour bitmaps only) too.
  if (glyph >= static_cast<GlyphId>(impl_->face->num_glyphs) ||
      FT_Get_Advance(impl_->face, glyph, kUnscaledLoadFlags, &value) != 0) {
    return 0.0;
  }
  return static_cast<double>(value);
}

Status Font::append_glyph(GlyphId glyph, const Affine& font_to_user, PathBuilder& builder) const {
  CURVESCAN_PROPAGATE(check_glyph(*impl_, glyph));
  if (FT_Load_Glyph(impl_->face, glyph, kUnscaledLoadFlags) != 0 ||
      impl_->face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
    return Error{ErrorKind::kCorruptInput, glyph_name(*impl_, glyph) + " cannot be loaded as an outline"};
  }
  DecomposeTarget target{&builder, font_to_user, 1.0, false};
  return decompose(impl_->face->glyph->outline, target, glyph_name(*impl_, glyph));
}

Result<Path> Font::glyph_path(GlyphId glyph, const Affine& font_to_user) const {
  PathBuilder builder;
  CURVESCAN_PROPAGATE(append_glyph(glyph, font_to_user, builder));
  return builder.build();
}

Result<Path> Font::freetype_scaled_glyph_path(GlyphId glyph, double pixels_per_em) const {
  CURVESCAN_PROPAGATE(check_glyph(*impl_, glyph));
  if (!(pixels_per_em >= 1.0 / 64.0 && pixels_per_em <= 16384.0)) {
    return Error{ErrorKind::kInvalidArgument, "pixels per em must be in [1/64, 16384]"};
  }
  const auto size_26_6 = static_cast<FT_F26Dot6>(std::lround(pixels_per_em * 64.0));
  if (FT_Set_Char_Size(impl_->face, 0, size_26_6, 72, 72) != 0 ||
      FT_Load_Glyph(impl_->face, glyph, kScaledLoadFlags) != 0 ||
      impl_->face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
    return Error{ErrorKind::kCorruptInput, glyph_name(*impl_, glyph) + " cannot be loaded as an outline"};
  }
  PathBuilder builder;
  DecomposeTarget target{&builder, Affine::identity(), 1.0 / 64.0, false};
  CURVESCAN_PROPAGATE(decompose(impl_->face->glyph->outline, target, glyph_name(*impl_, glyph)));
  return builder.build();
}

}  // namespace curvescan
