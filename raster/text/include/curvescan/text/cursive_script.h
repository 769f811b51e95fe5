// Cursive scripts (CSS Text 3, appendix E "Script Categorization"; CSS Text 4, "Letter-spacing and
// Cursive Scripts", #cursive-tracking): scripts whose letters join, so that a gap between them would
// break the word. CSS Text 4 does not apply letter-spacing between their letters (a user agent may
// lengthen the joins instead, which curvescan does not); the web-platform tests
// css/css-text/letter-spacing/letter-spacing-cursive-001 and -002 hold browsers to it.
#pragma once

namespace curvescan {

/// True when `c` belongs to a cursive script by its Unicode Script property (UAX #24, as HarfBuzz
/// reports it): Arabic, Hanifi Rohingya, Mandaic, Mongolian, N'Ko, Phags-pa and Syriac, the scripts CSS
/// Text 3 appendix E lists as cursive. Common and Inherited characters (spaces, digits, punctuation,
/// combining marks) are not cursive.
[[nodiscard]] bool is_cursive_script(char32_t c) noexcept;

}  // namespace curvescan
