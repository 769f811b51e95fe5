// Cursive scripts (cursive_script.h), by HarfBuzz's Unicode Script property.
#include "curvescan/text/cursive_script.h"

#include <hb.h>

namespace curvescan {

bool is_cursive_script(char32_t c) noexcept {
  switch (hb_unicode_script(hb_unicode_funcs_get_default(), static_cast<hb_codepoint_t>(c))) {
    case HB_SCRIPT_ARABIC:
    case HB_SCRIPT_HANIFI_ROHINGYA:
    case HB_SCRIPT_MANDAIC:
    case HB_SCRIPT_MONGOLIAN:
    case HB_SCRIPT_NKO:
    case HB_SCRIPT_PHAGS_PA:
    case HB_SCRIPT_SYRIAC:
      return true;
    default:
      return false;
  }
}

}  // namespace curvescan
