// The pictures of examples/results/crease/ (scripts/crease-pictures.sh): a window of a `panels` map seen at
// 1 texel -> 64 pixels, shaded three ways side by side - plain bilinear interpolation of the texel normals, the
// [Parilov05] reconstruction from the baked crease asset (formats/crease_reconstruction.h, the map's own
// normals read side-aware, no profile), and the exact normals of the panel surface (libbake/gen/panels.h) -
// and, for each method, its angular error against the exact normals over the window. Two input maps:
// `gen` (what `microbake gen panels` writes: central differences, so texels next to a crease mix both sides)
// and `exact` (the exact normals point-sampled at the texel centres); the curves are the exact creases.
//
// It is also the smallest example of a renderer using a crease asset: the bake is serialized and read back
// through formats/ (Asset::parse, read_crease_field), then per pixel reconstruct_crease + crease_normal.
//
//   crease_pictures SIZE SEED X0 Y0 W H OUT_DIR
// writes OUT_DIR/panels_gen.png, OUT_DIR/panels_exact.png and OUT_DIR/panels_profiles.png (the exact map under
// the four Eq. (1) profiles: v, rounded, step, table); the window is texels [X0, X0 + W) x [Y0, Y0 + H).
// Shading (linear, no tone mapping): Lambert plus a Blinn-Phong highlight (exponent 64) for a light from the
// upper left at 45 degrees elevation, viewed from straight above.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "formats/asset.h"
#include "formats/crease_reconstruction.h"
#include "formats/error.h"
#include "libbake/crease/crease_asset.h"
#include "libbake/gen/generator.h"
#include "libbake/gen/panels.h"
#include "libbake/image/image_io.h"

namespace {

constexpr int kPixelsPerTexel = 64;
constexpr int kGap = 8;  // pixels between the three panels

double shade(const double n[3]) {
  const mbk::Vec3 l = mbk::Vec3(-0.5, 0.5, 0.7071).normalized(), h = (l + mbk::Vec3(0, 0, 1)).normalized();
  const double ndl = std::max(0.0, n[0] * l.x() + n[1] * l.y() + n[2] * l.z());
  const double ndh = std::max(0.0, n[0] * h.x() + n[1] * h.y() + n[2] * h.z());
  return 0.55 * ndl + 0.45 * std::pow(ndh, 64.0);
}

double angle_degrees(const double n[3], const mbk::Vec3& e) {
  return std::acos(std::clamp(n[0] * e.x() + n[1] * e.y() + n[2] * e.z(), -1.0, 1.0)) * 180.0 / M_PI;
}

void render(const mbk::CreaseField& field, const mbk::PanelLayout& layout, int x0, int y0, int w, int h,
            const std::string& name, const std::string& path) {
  mbk::CreaseProfile none;  // b = 1: the map's own normals, reconstructed side-aware
  none.blend_start = none.blend_end = 0.0;
  const int pw = w * kPixelsPerTexel, ph = h * kPixelsPerTexel;
  mbk::Image image;
  image.width = uint32_t(3 * pw + 2 * kGap);
  image.height = uint32_t(ph);
  image.channels = 3;
  image.pixels.assign(size_t(image.width) * image.height * 3, 1.0f);
  double sum2[2] = {0, 0};
  uint64_t above10[2] = {0, 0}, count = 0;
  for (int py = 0; py < ph; ++py)
    for (int px = 0; px < pw; ++px) {
      const double x = x0 + (px + 0.5) / kPixelsPerTexel, y = y0 + (py + 0.5) / kPixelsPerTexel;
      double n[3][3];
      mbk::bilinear_normal(field, x, y, n[0]);
      mbk::crease_normal(mbk::reconstruct_crease(field, x, y), none, n[1]);
      const mbk::Vec3 exact = mbk::panel_normal(layout, mbk::Vec2(x, y));
      for (int c = 0; c < 3; ++c) n[2][c] = exact[c];
      for (int k = 0; k < 3; ++k) {
        const float v = float(shade(n[k]));
        for (int c = 0; c < 3; ++c) image.at(uint32_t(k * (pw + kGap) + px), uint32_t(py), uint32_t(c)) = v;
      }
      for (int k = 0; k < 2; ++k) {
        const double a = angle_degrees(n[k], exact);
        sum2[k] += a * a;
        above10[k] += a > 10.0;
      }
      ++count;
    }
  mbk::save_image(path, image, {8, 32});
  const char* methods[2] = {"bilinear", "crease"};
  for (int k = 0; k < 2; ++k)
    std::printf("%s %s: RMS %.2f degrees, %.1f%% of pixels more than 10 degrees off the exact normals\n", name.c_str(),
                methods[k], std::sqrt(sum2[k] / double(count)), 100.0 * double(above10[k]) / double(count));
}

// [Parilov05] Fig. 10: the same crease network under Eq. (1) with each profile kind, the map's normals beyond
// the blend band; one panel per profile, side by side.
void render_profiles(const mbk::CreaseField& field, int x0, int y0, int w, int h, const std::string& path) {
  std::vector<mbk::CreaseProfile> profiles(4);
  profiles[0].kind = mbk::CreaseProfileKind::v;
  profiles[1].kind = mbk::CreaseProfileKind::rounded;
  profiles[2].kind = mbk::CreaseProfileKind::step;
  profiles[3].kind = mbk::CreaseProfileKind::table;
  profiles[3].table = {0.0, 0.6, 0.7, 0.6, 0.5};  // a lip: up, then back down
  for (mbk::CreaseProfile& p : profiles) {
    p.depth = 0.6;
    p.width = 0.8;
    p.blend_start = 0.5;
    p.blend_end = 0.8;
  }
  const int pw = w * kPixelsPerTexel, ph = h * kPixelsPerTexel;
  mbk::Image image;
  image.width = uint32_t(4 * pw + 3 * kGap);
  image.height = uint32_t(ph);
  image.channels = 3;
  image.pixels.assign(size_t(image.width) * image.height * 3, 1.0f);
  for (int py = 0; py < ph; ++py)
    for (int px = 0; px < pw; ++px) {
      const double x = x0 + (px + 0.5) / kPixelsPerTexel, y = y0 + (py + 0.5) / kPixelsPerTexel;
      const mbk::CreaseSample s = mbk::reconstruct_crease(field, x, y);
      for (int k = 0; k < 4; ++k) {
        double n[3];
        mbk::crease_normal(s, profiles[size_t(k)], n);
        const float v = float(shade(n));
        for (int c = 0; c < 3; ++c) image.at(uint32_t(k * (pw + kGap) + px), uint32_t(py), uint32_t(c)) = v;
      }
    }
  mbk::save_image(path, image, {8, 32});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 8) {
    std::fprintf(stderr, "usage: crease_pictures SIZE SEED X0 Y0 W H OUT_DIR\n");
    return 1;
  }
  try {
    const uint32_t size = uint32_t(std::stoul(argv[1])), seed = uint32_t(std::stoul(argv[2]));
    const int x0 = std::stoi(argv[3]), y0 = std::stoi(argv[4]), w = std::stoi(argv[5]), h = std::stoi(argv[6]);
    const std::string dir = argv[7];
    const mbk::MapSize map_size{size, size};
    const mbk::PanelLayout layout = mbk::panel_layout(map_size, seed);
    mbk::CurveSet curves;
    for (const mbk::CreaseSegment& s : mbk::panel_creases(layout)) curves.curves.push_back({{s.a, s.b}, false, ""});
    for (const bool point_sampled : {false, true}) {
      mbk::NormalMap map = mbk::generate_panels(map_size, seed, mbk::Progress::silent());
      if (point_sampled)
        for (uint32_t row = 0; row < size; ++row)
          for (uint32_t x = 0; x < size; ++x)
            map.at(x, row) = mbk::panel_normal(layout, mbk::Vec2(x + 0.5, row + 0.5)).cast<float>();
      const mbk::CreaseBakeOptions options;
      mbk::BakedCrease baked = mbk::bake_crease(map, curves, options, mbk::Progress::silent());
      const std::vector<uint8_t> bytes =
          mbk::crease_asset_writer(std::move(baked), options, mbk::InputRecord{}, mbk::CurvesRecord{}).serialize();
      const mbk::CreaseField field = mbk::read_crease_field(mbk::Asset::parse(bytes, "baked"));
      const std::string name = point_sampled ? "exact" : "gen";
      render(field, layout, x0, y0, w, h, name, dir + "/panels_" + name + ".png");
      if (point_sampled) render_profiles(field, x0, y0, w, h, dir + "/panels_profiles.png");
    }
    return 0;
  } catch (const mbk::Error& e) {
    std::fprintf(stderr, "crease_pictures: error: %s\n", e.message().c_str());
    return int(e.code());
  }
}
