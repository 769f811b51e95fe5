// Filter effects: eight SVG filter primitives at work, each on its own shape — a drop shadow, a glow
// (blur and merge), clouds (fractal noise through a colour matrix), an emboss (specular lighting of the
// blurred alpha), ripples (a displacement map driven by turbulence), an outline (dilation), hue rotations
// and an edge-detecting convolution. The drawing is an SVG document rendered by curvescan's SVG renderer
// (curvescan/svg/document.h) into the figure's canvas; the captions are the figure's own labels.
#include <string>
#include <string_view>

#include "curvescan/svg/document.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"

namespace curvescan::figure {

namespace {

constexpr std::string_view kFilterScene =
    R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="960" height="640">
  <defs>
    <filter id="shadow" x="-30%" y="-30%" width="160%" height="160%">
      <feDropShadow dx="8" dy="8" stdDeviation="6" flood-color="#1d2b3a" flood-opacity="0.55"/>
    </filter>
    <filter id="glow" x="-40%" y="-40%" width="180%" height="180%">
      <feGaussianBlur in="SourceGraphic" stdDeviation="9" result="halo"/>
      <feMerge><feMergeNode in="halo"/><feMergeNode in="halo"/><feMergeNode in="SourceGraphic"/></feMerge>
    </filter>
    <filter id="clouds" x="0" y="0" width="100%" height="100%" color-interpolation-filters="sRGB">
      <feTurbulence type="fractalNoise" baseFrequency="0.018" numOctaves="5" seed="7"/>
      <feColorMatrix type="matrix" values="0 0 0 0 0.25  0 0 0 0 0.45  0 0 0 0 0.85  -2.2 0 0 0 1.35"/>
      <feComposite in2="SourceGraphic" operator="in"/>
    </filter>
    <filter id="emboss" x="-10%" y="-10%" width="120%" height="120%">
      <feGaussianBlur in="SourceAlpha" stdDeviation="5" result="bump"/>
      <feSpecularLighting in="bump" surfaceScale="8" specularConstant="1" specularExponent="18"
                          lighting-color="#ffffff" result="shine">
        <fePointLight x="760" y="80" z="140"/>
      </feSpecularLighting>
      <feComposite in="shine" in2="SourceAlpha" operator="in" result="lit"/>
      <feComposite in="SourceGraphic" in2="lit" operator="arithmetic" k1="0" k2="1" k3="1" k4="0"/>
    </filter>
    <filter id="ripple" x="-10%" y="-10%" width="120%" height="120%">
      <feTurbulence type="turbulence" baseFrequency="0.022" numOctaves="2" seed="3" result="noise"/>
      <feDisplacementMap in="SourceGraphic" in2="noise" scale="20" xChannelSelector="R" yChannelSelector="G"/>
    </filter>
    <filter id="outline" x="-20%" y="-40%" width="140%" height="180%">
      <feMorphology in="SourceAlpha" operator="dilate" radius="4" result="fat"/>
      <feFlood flood-color="#e8a33d"/>
      <feComposite in2="fat" operator="in"/>
      <feMerge><feMergeNode/><feMergeNode in="SourceGraphic"/></feMerge>
    </filter>
    <filter id="hue90"><feColorMatrix type="hueRotate" values="90"/></filter>
    <filter id="hue200"><feColorMatrix type="hueRotate" values="200"/></filter>
    <filter id="edges" color-interpolation-filters="sRGB">
      <feConvolveMatrix order="3" kernelMatrix="-1 -1 -1  -1 8 -1  -1 -1 -1" preserveAlpha="true"/>
    </filter>
    <linearGradient id="warm" x1="0" y1="0" x2="1" y2="0">
      <stop offset="0" stop-color="#d7263d"/><stop offset="0.5" stop-color="#f4a259"/>
      <stop offset="1" stop-color="#f6e27f"/>
    </linearGradient>
    <pattern id="grid" width="20" height="20" patternUnits="userSpaceOnUse">
      <rect width="20" height="20" fill="#f4f1ea"/>
      <path d="M0 0.5H20M0.5 0V20" stroke="#3b6ea5" stroke-width="3"/>
    </pattern>
  </defs>
  <!-- Row 1 -->
  <path filter="url(#shadow)" fill="#f08a24" stroke="#9c4a00" stroke-width="3" stroke-linejoin="round"
        d="M127 102 L150 158 L210 162 L164 200 L179 258 L127 226 L75 258 L90 200 L44 162 L104 158 Z"/>
  <g filter="url(#glow)" fill="none" stroke-width="8">
    <circle cx="362" cy="182" r="62" stroke="#19b3c2"/>
    <circle cx="362" cy="182" r="30" stroke="#7a5cff"/>
  </g>
  <rect filter="url(#clouds)" x="495" y="92" width="200" height="180" rx="18" fill="black"/>
  <g filter="url(#emboss)">
    <rect x="740" y="100" width="180" height="164" rx="36" fill="#4f7d3a"/>
  </g>
  <!-- Row 2 -->
  <rect filter="url(#ripple)" x="32" y="362" width="190" height="170" fill="url(#grid)"/>
  <text filter="url(#outline)" x="362" y="482" font-family="DejaVu Sans" font-weight="bold" font-size="96"
        text-anchor="middle" fill="#23395d">Fx</text>
  <g>
    <rect x="500" y="362" width="190" height="50" fill="url(#warm)"/>
    <rect x="500" y="422" width="190" height="50" fill="url(#warm)" filter="url(#hue90)"/>
    <rect x="500" y="482" width="190" height="50" fill="url(#warm)" filter="url(#hue200)"/>
  </g>
  <g filter="url(#edges)">
    <rect x="735" y="362" width="190" height="170" fill="#ffffff"/>
    <circle cx="800" cy="430" r="42" fill="#2d6cdf"/>
    <path d="M820 520 L900 380 L920 520 Z" fill="#e0443e"/>
  </g>
</svg>)svg";

struct Caption {
  Point at;  // the centre of the caption's first line
  std::string_view primitive;
  std::string_view what;
};

}  // namespace

Result<Image> render_filter_effects() {
  Result<Figure> made = Figure::create(960, 640);
  if (!made) return made.error();
  Figure& figure = *made;
  figure.text("SVG filter effects, drawn by curvescan", {40.0, 48.0}, 28.0, kInk);

  Result<svg::Document> document = svg::Document::parse(kFilterScene);
  if (!document) return document.error();
  const Result<svg::DocumentMessages> drawn =
      document->draw(figure.canvas(), Affine::identity(), svg::RenderOptions{});
  if (!drawn) return drawn.error();
  // A warning means something of the scene was left out: the figure would not show what it says.
  if (!drawn->warnings.empty()) return Error{ErrorKind::kInvalidArgument, drawn->warnings.front()};

  const Caption captions[] = {
      {{127.0, 300.0}, "feDropShadow", "blurred, offset alpha"},
      {{362.0, 300.0}, "feGaussianBlur + feMerge", "a glow under the source"},
      {{595.0, 300.0}, "feTurbulence", "fractal noise as clouds"},
      {{830.0, 300.0}, "feSpecularLighting", "a point light on blurred alpha"},
      {{127.0, 570.0}, "feDisplacementMap", "a grid moved by turbulence"},
      {{362.0, 570.0}, "feMorphology", "dilated alpha as an outline"},
      {{595.0, 570.0}, "feColorMatrix", "hue rotated by 0, 90, 200 degrees"},
      {{830.0, 570.0}, "feConvolveMatrix", "a 3 x 3 edge detector"},
  };
  for (const Caption& caption : captions) {
    figure.text(caption.primitive, caption.at, 15.0, kInk, TextAnchor::kMiddle);
    figure.text(caption.what, {caption.at.x, caption.at.y + 19.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  }
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
