// Font: one face of a scalable font file (TrueType or CFF-flavoured OpenType), read by FreeType, whose
// glyph outlines become curvescan Paths exactly — TrueType quadratics as kQuad, CFF cubics as kCubic —
// unhinted, so they can be drawn at any size and under any transform by curvescan's own rasterizer.
//
// Units: font units ("design units", units_per_em() of them to the em) with y pointing up, as in the
// font file (OpenType spec, "glyf" and "CFF " tables). A caller maps them to user space with an Affine;
// text_layout.h does that for strings, with y pointing down as on a canvas.
//
// Glyph outlines are filled with the non-zero rule (OpenType spec "glyf": contours are oriented so that
// the filled area is to the right of the direction; CFF: Type 2 charstrings use non-zero winding).
//
// A Font is not thread-safe: FreeType faces are not (FreeType docs, "Multi-threading"); use one Font per
// thread. It owns the file's bytes, so it stays valid when the file changes on disk.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/status.h"

namespace curvescan {

/// A glyph index within one face; 0 is the font's .notdef glyph (OpenType spec, "Recommendations for
/// OpenType fonts": glyph 0 must be the missing-character glyph).
using GlyphId = std::uint32_t;
inline constexpr GlyphId kNotdefGlyph = 0;

/// Largest font file curvescan reads into memory (the largest CJK fonts are ~20 MiB; 64 MiB leaves room).
inline constexpr std::size_t kMaxFontFileBytes = std::size_t{64} << 20;

/// How the face stores its outlines.
enum class OutlineFormat {
  kTrueType,  ///< "glyf" table: quadratic B-splines (on/off-curve points) -> kQuad segments
  kCff,       ///< "CFF " / "CFF2" table: cubic Béziers -> kCubic segments
  kOther,     ///< another scalable format FreeType reads (Type 1, ...): converted the same way
};

/// Vertical metrics in font units, y up (hhea table through FreeType's FT_FaceRec fields).
struct FontMetrics {
  double units_per_em = 0.0;
  double ascender = 0.0;     ///< top of the line above the baseline (> 0)
  double descender = 0.0;    ///< bottom of the line below the baseline (usually < 0)
  double line_height = 0.0;  ///< baseline-to-baseline distance: ascender - descender + line gap
  // Decoration and baseline metrics (OpenType "post" and "OS/2" tables), for underline, overline,
  // line-through, sub/superscript shifts and the middle baseline. Where the font has no such value the
  // fallback is the one CSS and browsers use, named beside each.
  /// The underline stroke's centre, < 0 below the baseline: half a thickness below post.underlinePosition,
  /// which OpenType defines as the top of the stroke (a face without sfnt tables: FreeType's centre);
  /// else -0.1 em
  double underline_position = 0.0;
  double underline_thickness = 0.0;  ///< post.underlineThickness; else units_per_em / 14
  /// OS/2 yStrikeoutPosition: the top of the stroke above the baseline (OpenType spec, OS/2 table: "the
  /// position of the top of the strikeout stroke relative to the baseline"); else the top of a stroke
  /// centred on x_height / 2.
  double strikeout_position = 0.0;
  double strikeout_thickness = 0.0;  ///< OS/2 yStrikeoutSize; else the underline thickness
  double x_height = 0.0;             ///< OS/2 sxHeight (version 2+); else 0.5 em (CSS Values 4: 1ex = 0.5em)
  double subscript_offset = 0.0;     ///< OS/2 ySubscriptYOffset, > 0 downwards; else 0.2 em
  double superscript_offset = 0.0;   ///< OS/2 ySuperscriptYOffset, > 0 upwards; else 0.33 em
};

/// One coordinate of a variable font's design space (OpenType "fvar" table; CSS Fonts 4 section 7.13,
/// font-variation-settings): the axis tag (four ASCII letters packed big-endian, as OpenType and
/// HarfBuzz's HB_TAG do: "wght", "wdth", "slnt", "ital", "opsz", ...) and the value in the axis's own
/// units (wght 1..1000, wdth a percentage, slnt degrees counter-clockwise, opsz points).
struct FontVariation {
  std::uint32_t tag = 0;
  double value = 0.0;
  friend bool operator==(const FontVariation&, const FontVariation&) = default;
  friend auto operator<=>(const FontVariation&, const FontVariation&) = default;
};

class Font {
 public:
  /// Reads face `face_index` of the font file at `file`, at most kMaxFontFileBytes + 1 bytes of it.
  /// kIoError when the file cannot be read, kInvalidArgument when it is not a regular file (a device,
  /// FIFO, socket or directory), kLimitExceeded beyond kMaxFontFileBytes, and from_bytes's errors.
  [[nodiscard]] static Result<Font> open(const std::filesystem::path& file, int face_index = 0);
  /// The same from bytes already in memory; `name` is used in messages. kCorruptInput when an sfnt
  /// (TrueType/OpenType) file's table directory or one of its tables runs past the end of the bytes
  /// (a cut file), or when FreeType cannot parse it as a font; kUnsupported for a face without scalable
  /// outlines (a bitmap-only font).
  [[nodiscard]] static Result<Font> from_bytes(std::vector<unsigned char> bytes, int face_index,
                                               const std::string& name);

  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;
  ~Font();

  [[nodiscard]] const std::string& family_name() const noexcept;
  [[nodiscard]] const std::string& style_name() const noexcept;
  /// The file name or the name given to from_bytes, for messages.
  [[nodiscard]] const std::string& source_name() const noexcept;
  [[nodiscard]] OutlineFormat outline_format() const noexcept;
  [[nodiscard]] FontMetrics metrics() const noexcept;
  [[nodiscard]] std::size_t glyph_count() const noexcept;

  /// True when the face is a variable font (it has an "fvar" table) with an axis `tag`.
  [[nodiscard]] bool has_variation_axis(std::uint32_t tag) const noexcept;
  /// True when the face is a variable font (it has an "fvar" table with at least one axis).
  [[nodiscard]] bool is_variable() const noexcept;
  /// Moves a variable font to the design coordinates `variations`, later entries winning over earlier
  /// ones for the same axis: outlines (FreeType), shaping and advances (HarfBuzz) all follow. Axes not
  /// named keep the coordinate the face was opened with (its default or the named instance fontconfig
  /// chose); a value outside an axis's range is clamped to it, and a tag the face has no axis for is
  /// ignored (CSS Fonts 4 7.13: "values ... not supported by the font are ignored"; OpenType "fvar":
  /// coordinates are clamped to the axis range). No effect on a face without axes. kCorruptInput when
  /// FreeType refuses the coordinates; NaN values are ignored.
  [[nodiscard]] Status set_variations(std::span<const FontVariation> variations);

  /// The glyph the font's character map gives `character`, or kNotdefGlyph when it has none.
  [[nodiscard]] GlyphId glyph_for(char32_t character) const noexcept;
  /// Unhinted horizontal advance of `glyph` in font units (hmtx / CFF width); 0 for an invalid glyph.
  [[nodiscard]] double advance(GlyphId glyph) const noexcept;

  /// Appends the outline of `glyph` (font units, y up) mapped by `font_to_user`, one closed contour per font
  /// contour, to `builder`; curves stay curves (affine invariance; Ince, *Curves*). kInvalidArgument for a
  /// glyph index outside the face, kCorruptInput when FreeType cannot load the glyph, and the builder's own
  /// error if the transform overflows a coordinate. An empty glyph (a space) appends nothing.
  [[nodiscard]] Status append_glyph(GlyphId glyph, const Affine& font_to_user, PathBuilder& builder) const;
  /// The outline of `glyph` mapped by `font_to_user` as a Path of its own.
  [[nodiscard]] Result<Path> glyph_path(GlyphId glyph, const Affine& font_to_user = Affine::identity()) const;
  /// The outline exactly as FreeType scales it for FT_Render_Glyph at `pixels_per_em` (set with
  /// FT_Set_Char_Size in 26.6, loaded with FT_LOAD_NO_HINTING, so every coordinate is rounded to 1/64
  /// pixel), in pixels with y up and the glyph origin at (0, 0). This is the outline FreeType's own
  /// renderer sees, for comparisons with it; text drawing uses glyph_path, which does not round.
  /// kInvalidArgument when pixels_per_em is not in [1/64, 16384].
  [[nodiscard]] Result<Path> freetype_scaled_glyph_path(GlyphId glyph, double pixels_per_em) const;

  /// FreeType and HarfBuzz state (raster/text/font_face_p.h), for the layout code of this library.
  struct Impl;
  [[nodiscard]] const Impl& impl() const noexcept { return *impl_; }

 private:
  explicit Font(std::unique_ptr<Impl> impl) noexcept;
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvescan
