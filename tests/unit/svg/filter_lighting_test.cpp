// feDiffuseLighting and feSpecularLighting (Filter Effects 1, sections 15.14 and 15.22) with the three light
// sources. The oracle below computes each pixel the specification's way: the surface normal from the nine
// Sobel tables exactly as printed (interior, four edges, four corners), then the Phong terms with L, H and
// the spot light's Lr written out. The kernel derives the tables from one rule (lighting.cpp), so agreement
// on every pixel class checks that rule. Both compute in double; the kernel stores floats, so channels
// agree within 1e-5 (float rounding of values <= 1 plus the different operation order of the normal sum).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>

#include "filter_kernel_support.h"
#include "svg/filter/lighting.h"

using namespace curvescan;
using namespace curvescan::svg::detail::filter;
using curvescan::svg::testing::compare_images;
using curvescan::svg::testing::PrimitiveXml;
using curvescan::svg::testing::random_image;
using curvescan::svg::testing::same_inside_and_transparent_outside;
using curvescan::svg::testing::transparent_outside;

namespace {

struct SobelTable {
  double factor_x;
  int kx[3][3];
  double factor_y;
  int ky[3][3];
};

// The tables of Filter Effects 1, 15.14 (SVG 1.1, 15.14), indexed [row][column] with the pixel in the
// centre; row 0 is above the pixel.
const SobelTable kTopLeft = {
    2.0 / 3, {{0, 0, 0}, {0, -2, 2}, {0, -1, 1}}, 2.0 / 3, {{0, 0, 0}, {0, -2, -1}, {0, 2, 1}}};
const SobelTable kTopRow = {
    1.0 / 3, {{0, 0, 0}, {-2, 0, 2}, {-1, 0, 1}}, 1.0 / 2, {{0, 0, 0}, {-1, -2, -1}, {1, 2, 1}}};
const SobelTable kTopRight = {
    2.0 / 3, {{0, 0, 0}, {-2, 2, 0}, {-1, 1, 0}}, 2.0 / 3, {{0, 0, 0}, {-1, -2, 0}, {1, 2, 0}}};
const SobelTable kLeftColumn = {
    1.0 / 2, {{0, -1, 1}, {0, -2, 2}, {0, -1, 1}}, 1.0 / 3, {{0, -2, -1}, {0, 0, 0}, {0, 2, 1}}};
const SobelTable kInterior = {
    1.0 / 4, {{-1, 0, 1}, {-2, 0, 2}, {-1, 0, 1}}, 1.0 / 4, {{-1, -2, -1}, {0, 0, 0}, {1, 2, 1}}};
const SobelTable kRightColumn = {
    1.0 / 2, {{-1, 1, 0}, {-2, 2, 0}, {-1, 1, 0}}, 1.0 / 3, {{-1, -2, 0}, {0, 0, 0}, {1, 2, 0}}};
const SobelTable kBottomLeft = {
    2.0 / 3, {{0, -1, 1}, {0, -2, 2}, {0, 0, 0}}, 2.0 / 3, {{0, -2, -1}, {0, 2, 1}, {0, 0, 0}}};
const SobelTable kBottomRow = {
    1.0 / 3, {{-1, 0, 1}, {-2, 0, 2}, {0, 0, 0}}, 1.0 / 2, {{-1, -2, -1}, {1, 2, 1}, {0, 0, 0}}};
const SobelTable kBottomRight = {
    2.0 / 3, {{-1, 1, 0}, {-2, 2, 0}, {0, 0, 0}}, 2.0 / 3, {{-1, -2, 0}, {1, 2, 0}, {0, 0, 0}}};

const SobelTable& table_for(PixelRect area, int x, int y) {
  const bool top = y == area.y0, bottom = y == area.y1 - 1, left = x == area.x0, right = x == area.x1 - 1;
  if (top) return left ? kTopLeft : (right ? kTopRight : kTopRow);
  if (bottom) return left ? kBottomLeft : (right ? kBottomRight : kBottomRow);
  return left ? kLeftColumn : (right ? kRightColumn : kInterior);
}

std::array<double, 3> oracle_normal(const FilterImage& in, PixelRect area, int x, int y,
                                    double surface_scale) {
  const SobelTable& t = table_for(area, x, y);
  double sx = 0.0, sy = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (t.kx[i][j] == 0 && t.ky[i][j] == 0) continue;  // also keeps reads inside the area
      const double a = in.pixel(x + j - 1, y + i - 1)[3];
      sx += t.kx[i][j] * a;
      sy += t.ky[i][j] * a;
    }
  }
  const double nx = -surface_scale * t.factor_x * sx, ny = -surface_scale * t.factor_y * sy;
  const double len = std::sqrt(nx * nx + ny * ny + 1.0);
  return {nx / len, ny / len, 1.0 / len};
}

double rad(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

/// L and Lr at surface point (x, y, z) in filter pixels, the light's numbers mapped the documented way.
void oracle_light(const LightSource& light, const FilterSpace& space, double x, double y, double z,
                  const std::array<float, 3>& color, std::array<double, 3>& l, std::array<double, 3>& lr) {
  lr = {color[0], color[1], color[2]};
  if (light.kind == LightKind::kDistant) {
    l = {std::cos(rad(light.azimuth)) * std::cos(rad(light.elevation)),
         std::sin(rad(light.azimuth)) * std::cos(rad(light.elevation)), std::sin(rad(light.elevation))};
    return;
  }
  const auto place = [&](double px, double py, double pz) {
    const Point p = space.to_pixels({space.user_x(px), space.user_y(py)});
    return std::array<double, 3>{p.x, p.y, space.length_to_pixels(space.user_length(pz))};
  };
  const auto pos = place(light.x, light.y, light.z);
  std::array<double, 3> v = {pos[0] - x, pos[1] - y, pos[2] - z};
  double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  l = {v[0] / len, v[1] / len, v[2] / len};
  if (light.kind == LightKind::kPoint) return;
  const auto at = place(light.points_at_x, light.points_at_y, light.points_at_z);
  std::array<double, 3> s = {at[0] - pos[0], at[1] - pos[1], at[2] - pos[2]};
  len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  const double minus_l_dot_s = -(l[0] * s[0] + l[1] * s[1] + l[2] * s[2]) / len;
  const bool inside = minus_l_dot_s > 0.0 && (!light.limiting_cone_angle ||
                                              minus_l_dot_s >= std::cos(rad(*light.limiting_cone_angle)));
  const double f = inside ? std::pow(minus_l_dot_s, light.spot_exponent) : 0.0;
  lr = {color[0] * f, color[1] * f, color[2] * f};
}

// `edge`: the height map's edge, whose tables apply (by default the subregion `area`; the input's own
// subregion united with it when the input reaches beyond).
FilterImage oracle(const FilterImage& in, PixelRect area, const FilterSpace& space, const LightSource& light,
                   double surface_scale, std::array<float, 3> color, bool specular, double constant,
                   double exponent, std::optional<PixelRect> edge = std::nullopt) {
  FilterImage out(in.width, in.height);
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      const auto n = oracle_normal(in, edge.value_or(area), x, y, surface_scale);
      std::array<double, 3> l{}, lr{};
      oracle_light(light, space, x, y, surface_scale * in.pixel(x, y)[3], color, l, lr);
      double k = 0.0;
      if (!specular) {
        k = constant * (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]);
      } else {
        std::array<double, 3> h = {l[0], l[1], l[2] + 1.0};
        const double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        const double n_dot_h = (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / hl;
        k = constant * std::pow(std::max(n_dot_h, 0.0), exponent);
      }
      float* p = out.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        p[c] = static_cast<float>(std::clamp(k * lr[static_cast<std::size_t>(c)], 0.0, 1.0));
      p[3] = specular ? std::max({p[0], p[1], p[2]}) : 1.0f;
    }
  }
  return out;
}

/// A height map with structure at several scales (random alpha alone would make every normal extreme).
FilterImage bumpy_image(int w, int h, std::uint32_t seed) {
  FilterImage image = random_image(w, h, seed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* p = image.pixel(x, y);
      const float smooth = static_cast<float>(0.5 + 0.4 * std::sin(x * 0.3) * std::cos(y * 0.2));
      const float a = 0.8f * smooth + 0.2f * p[3];
      for (int c = 0; c < 3; ++c) p[c] = p[3] > 0.0f ? p[c] / p[3] * a : 0.0f;
      p[3] = a;
    }
  return image;
}

}  // namespace

TEST_CASE("lighting: diffuse and specular match the specification's tables and formulas",
          "[svg][filter][lighting]") {
  FilterSpace scaled;
  scaled.scale_x = 2.0;
  scaled.scale_y = 1.5;
  scaled.origin_x = -3.0;
  scaled.origin_y = 4.0;
  FilterSpace bbox_units;
  bbox_units.bounding_box_units = true;
  bbox_units.bbox = Rect{2.0, 3.0, 30.0, 25.0};
  const char* lights[] = {
      R"(<feDistantLight azimuth="35" elevation="50"/>)",
      R"(<fePointLight x="10" y="8" z="15"/>)",
      R"(<feSpotLight x="30" y="2" z="20" pointsAtX="12" pointsAtY="18" pointsAtZ="0" specularExponent="3"/>)",
      R"(<feSpotLight x="0" y="0" z="25" pointsAtX="20" pointsAtY="20" limitingConeAngle="-20"/>)",
  };
  const std::array<float, 3> color = {1.0f, 0.7f, 0.3f};
  const FilterImage in = bumpy_image(36, 30, 11);
  for (const FilterSpace& space : {FilterSpace{}, scaled}) {
    for (const char* light : lights) {
      for (const PixelRect area : {PixelRect{0, 0, 36, 30}, PixelRect{4, 3, 31, 27}}) {
        const std::string diffuse_xml =
            std::string(R"(<feDiffuseLighting surfaceScale="3" diffuseConstant="1.3">)") + light +
            "</feDiffuseLighting>";
        const PrimitiveXml diffuse_doc(diffuse_xml);
        std::string error;
        const auto diffuse = read_diffuse_lighting(diffuse_doc.element(), error);
        REQUIRE(diffuse);
        FilterImage out(36, 30);
        render_diffuse_lighting(*diffuse, space, area, in, color, out);
        auto diff = compare_images(out, oracle(in, area, space, diffuse->light, 3.0, color, false, 1.3, 1.0));
        INFO(diffuse_xml << " worst at " << diff.x << "," << diff.y << " channel " << diff.channel);
        CHECK(diff.max_diff <= 1e-5);
        CHECK(transparent_outside(out, area));
        // Only the needed pixels: the same values there (the same arithmetic: exactly), nothing else.
        const PixelRect written{2, 5, 20, 12};
        FilterImage part(36, 30);
        render_diffuse_lighting(*diffuse, space, area, in, color, part, written);
        CHECK(same_inside_and_transparent_outside(part, out, area.intersect(written)));

        const std::string specular_xml =
            std::string(
                R"(<feSpecularLighting surfaceScale="-2" specularConstant="0.9" specularExponent="12">)") +
            light + "</feSpecularLighting>";
        const PrimitiveXml specular_doc(specular_xml);
        const auto specular = read_specular_lighting(specular_doc.element(), error);
        REQUIRE(specular);
        FilterImage spec_out(36, 30);
        render_specular_lighting(*specular, space, area, in, color, spec_out);
        diff =
            compare_images(spec_out, oracle(in, area, space, specular->light, -2.0, color, true, 0.9, 12.0));
        INFO(specular_xml << " worst at " << diff.x << "," << diff.y << " channel " << diff.channel);
        CHECK(diff.max_diff <= 1e-5);
        // The input exists beyond the subregion (its own subregion is the whole image): the normals at the
        // subregion's border read it there, with the tables of interior pixels; the image's edge is the
        // height map's edge.
        FilterImage beyond(36, 30);
        render_diffuse_lighting(*diffuse, space, area, in, color, beyond, std::nullopt, in.bounds());
        diff = compare_images(
            beyond, oracle(in, area, space, diffuse->light, 3.0, color, false, 1.3, 1.0, in.bounds()));
        INFO("reading beyond the subregion: worst at " << diff.x << "," << diff.y << " channel "
                                                       << diff.channel);
        CHECK(diff.max_diff <= 1e-5);
        CHECK(transparent_outside(beyond, area));
        FilterImage spec_beyond(36, 30);
        render_specular_lighting(*specular, space, area, in, color, spec_beyond, std::nullopt, in.bounds());
        diff = compare_images(
            spec_beyond, oracle(in, area, space, specular->light, -2.0, color, true, 0.9, 12.0, in.bounds()));
        CHECK(diff.max_diff <= 1e-5);
      }
    }
  }
  // primitiveUnits="objectBoundingBox": the point light's x, y are fractions of the box and z a fraction
  // of its diagonal / sqrt(2).
  const PrimitiveXml doc(
      R"(<feDiffuseLighting><fePointLight x="0.5" y="0.25" z="0.4"/></feDiffuseLighting>)");
  std::string error;
  const auto params = read_diffuse_lighting(doc.element(), error);
  REQUIRE(params);
  FilterImage out(36, 30);
  render_diffuse_lighting(*params, bbox_units, {0, 0, 36, 30}, in, color, out);
  CHECK(
      compare_images(out, oracle(in, {0, 0, 36, 30}, bbox_units, params->light, 1.0, color, false, 1.0, 1.0))
          .max_diff <= 1e-5);
}

TEST_CASE("lighting: flat surfaces give the textbook values", "[svg][filter][lighting]") {
  // On a flat surface N = (0, 0, 1): diffuse = kd * sin(elevation) for a distant light; specular with
  // elevation 90 has H = N, so ks * 1^exp = ks, alpha = max channel.
  FilterImage flat(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) flat.pixel(x, y)[3] = 0.5f;
  const PrimitiveXml d(
      R"(<feDiffuseLighting diffuseConstant="0.8"><feDistantLight elevation="30"/></feDiffuseLighting>)");
  std::string error;
  FilterImage out(8, 8);
  render_diffuse_lighting(*read_diffuse_lighting(d.element(), error), FilterSpace{}, {0, 0, 8, 8}, flat,
                          {1.0f, 0.5f, 0.0f}, out);
  CHECK(out.pixel(0, 7)[0] == Approx(0.8 * 0.5).margin(1e-6));  // sin 30 = 0.5, float storage
  CHECK(out.pixel(4, 4)[1] == Approx(0.8 * 0.5 * 0.5).margin(1e-6));
  CHECK(out.pixel(4, 4)[2] == 0.0f);
  CHECK(out.pixel(4, 4)[3] == 1.0f);
  const PrimitiveXml s(
      R"(<feSpecularLighting specularConstant="0.6" specularExponent="20"><feDistantLight elevation="90"/></feSpecularLighting>)");
  FilterImage spec(8, 8);
  render_specular_lighting(*read_specular_lighting(s.element(), error), FilterSpace{}, {0, 0, 8, 8}, flat,
                           {0.5f, 1.0f, 0.25f}, spec);
  CHECK(spec.pixel(3, 3)[1] == Approx(0.6).margin(1e-6));
  CHECK(spec.pixel(3, 3)[0] == Approx(0.3).margin(1e-6));
  CHECK(spec.pixel(3, 3)[3] == Approx(0.6).margin(1e-6));
}

TEST_CASE("lighting: degenerate subregions do not read outside", "[svg][filter][lighting]") {
  // One pixel wide or high: no neighbour along that axis, the normal's component is 0. Under ASan an
  // out-of-area read of a 1 x 1 image would be reported.
  const PrimitiveXml d(
      R"(<feDiffuseLighting surfaceScale="5"><feDistantLight elevation="90"/></feDiffuseLighting>)");
  std::string error;
  const auto params = read_diffuse_lighting(d.element(), error);
  REQUIRE(params);
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{1, 6}, std::pair{6, 1}}) {
    const FilterImage in = random_image(w, h, 3);
    FilterImage out(w, h);
    render_diffuse_lighting(*params, FilterSpace{}, {0, 0, w, h}, in, {1.0f, 1.0f, 1.0f}, out);
    if (w == 1 && h == 1) CHECK(out.pixel(0, 0)[0] == 1.0f);  // flat: N = (0, 0, 1) = L
  }
}

TEST_CASE("lighting: attributes, light sources and errors", "[svg][filter][lighting]") {
  std::string error;
  {
    const PrimitiveXml doc(R"(<feSpecularLighting><fePointLight/></feSpecularLighting>)");
    const auto p = read_specular_lighting(doc.element(), error);
    REQUIRE(p);
    CHECK(p->surface_scale == 1.0);
    CHECK(p->specular_constant == 1.0);
    CHECK(p->specular_exponent == 1.0);
    CHECK_FALSE(p->kernel_unit_length);
    CHECK(p->light.kind == LightKind::kPoint);
  }
  {
    // The first light source child counts; prefixed names are read by their local name.
    const PrimitiveXml doc(
        R"(<svg:feDiffuseLighting xmlns:svg="http://www.w3.org/2000/svg" kernelUnitLength="2 3">
        <svg:desc/><svg:feSpotLight x="1" pointsAtZ="-4" limitingConeAngle="30" specularExponent="7"/>
        <svg:feDistantLight/></svg:feDiffuseLighting>)");
    const auto p = read_diffuse_lighting(doc.element(), error);
    REQUIRE(p);
    CHECK(p->light.kind == LightKind::kSpot);
    CHECK(p->light.x == 1.0);
    CHECK(p->light.points_at_z == -4.0);
    CHECK(p->light.spot_exponent == 7.0);
    CHECK(p->light.limiting_cone_angle == 30.0);
    REQUIRE(p->kernel_unit_length);
    CHECK(p->kernel_unit_length->y == 3.0);
  }
  const char* errors[] = {
      R"(<feDiffuseLighting/>)",
      R"(<feDiffuseLighting><feFlood/></feDiffuseLighting>)",
      R"(<feDiffuseLighting kernelUnitLength="0"><feDistantLight/></feDiffuseLighting>)",
      R"(<feDiffuseLighting kernelUnitLength="1 -2"><feDistantLight/></feDiffuseLighting>)",
  };
  for (const char* xml : errors) {
    const PrimitiveXml doc(xml);
    error.clear();
    CHECK_FALSE(read_diffuse_lighting(doc.element(), error));
    CHECK_FALSE(error.empty());
  }
  {
    // A negative kd is no error: clamped to 0 (an unlit, opaque black surface), as Chrome renders it.
    const PrimitiveXml doc(
        R"(<feDiffuseLighting diffuseConstant="-1"><feDistantLight/></feDiffuseLighting>)");
    const auto p = read_diffuse_lighting(doc.element(), error);
    REQUIRE(p);
    CHECK(p->diffuse_constant == 0.0);
  }
  for (const char* exponent : {"-10", "0"}) {
    // A spot light's exponent <= 0 focuses nothing: its initial value 1 is used.
    const PrimitiveXml doc(std::string(R"(<feDiffuseLighting><feSpotLight specularExponent=")") + exponent +
                           R"("/></feDiffuseLighting>)");
    const auto p = read_diffuse_lighting(doc.element(), error);
    REQUIRE(p);
    CHECK(p->light.spot_exponent == 1.0);
  }
  const char* specular_errors[] = {
      R"(<feSpecularLighting specularExponent="0.5"><feDistantLight/></feSpecularLighting>)",
      R"(<feSpecularLighting specularExponent="128.5"><feDistantLight/></feSpecularLighting>)",
      R"(<feSpecularLighting specularConstant="-0.1"><feDistantLight/></feSpecularLighting>)",
  };
  for (const char* xml : specular_errors) {
    const PrimitiveXml doc(xml);
    error.clear();
    CHECK_FALSE(read_specular_lighting(doc.element(), error));
    CHECK_FALSE(error.empty());
  }
}

TEST_CASE("lighting: hostile numbers stay finite", "[svg][filter][lighting]") {
  const char* xmls[] = {
      R"(<feSpecularLighting surfaceScale="1e308" specularConstant="1e308" specularExponent="128">
           <feSpotLight x="1e308" y="-1e308" z="1e308" pointsAtX="1e308" specularExponent="-1e308"/></feSpecularLighting>)",
      R"(<feSpecularLighting surfaceScale="NaN" specularExponent="1e-300"><feSpotLight specularExponent="1e308"
           limitingConeAngle="1e308"/></feSpecularLighting>)",
  };
  for (const char* xml : xmls) {
    const PrimitiveXml doc(xml);
    std::string error;
    const auto p = read_specular_lighting(doc.element(), error);
    if (!p) continue;  // an error is an acceptable answer; a crash or NaN pixels are not
    const FilterImage in = random_image(9, 7, 5);
    FilterImage out(9, 7);
    render_specular_lighting(*p, FilterSpace{}, {0, 0, 9, 7}, in, {0.0f, 1.0f, 1.0f}, out);
    for (const float v : out.rgba) CHECK((v >= 0.0f && v <= 1.0f));
  }
}
