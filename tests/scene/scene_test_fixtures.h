// Shared by the scene and eval tests: normal maps written as float EXR (exact values), and
// a small scene (a plane seen at an angle, a sphere and a bent quad; a point light, a directional light and
// a sky) whose materials a test chooses.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk::testing {

// Texel (x, row) = normal(x, row), stored as float RGB (the loader takes float images as the vector).
inline void write_normal_map(const std::filesystem::path& path, uint32_t width, uint32_t height,
                             const std::function<Vec3(uint32_t, uint32_t)>& normal) {
  Image image;
  image.width = width;
  image.height = height;
  image.channels = 3;
  image.pixels.resize(size_t(width) * height * 3);
  for (uint32_t row = 0; row < height; ++row)
    for (uint32_t x = 0; x < width; ++x) {
      const Vec3 n = normal(x, row).normalized();
      for (uint32_t c = 0; c < 3; ++c) image.at(x, row, c) = float(n[c]);
    }
  save_image(path, image);
}

// A bumpy map with slopes in both directions, non-power-of-two.
inline void write_bumpy_map(const std::filesystem::path& path, uint32_t width = 24, uint32_t height = 20) {
  write_normal_map(path, width, height, [&](uint32_t x, uint32_t row) {
    const double u = 2 * 3.14159265358979 * x / width, v = 2 * 3.14159265358979 * row / height;
    return Vec3(0.6 * std::sin(u) * std::cos(2 * v), 0.5 * std::cos(3 * u + v), 1.0);
  });
}

// Camera above a plane, looking at a sphere and a bent quad; every shape uses material "a", the sphere
// "b" and the bent quad "c" (materials given by the test, which must define a, b and c).
inline nlohmann::json small_scene(const nlohmann::json& materials, uint32_t width = 40, uint32_t height = 30) {
  return {
      {"camera",
       {{"position", {0.0, 1.5, 4.0}},
        {"look_at", {0.0, 0.4, 0.0}},
        {"fov_y", 45},
        {"width", width},
        {"height", height}}},
      {"shapes",
       {{{"type", "plane"}, {"size", {30.0, 30.0}}, {"uv_scale", {12.0, 12.0}}, {"material", "a"}},
        {{"type", "sphere"},
         {"center", {-0.6, 0.7, 0.0}},
         {"radius", 0.7},
         {"uv_scale", {3.0, 2.0}},
         {"material", "b"}},
        {{"type", "bent_quad"},
         {"center", {1.0, 0.6, -0.5}},
         {"normal", {0.0, 0.0, 1.0}},
         {"size", {1.2, 1.0}},
         {"angle", 80},
         {"material", "c"}}}},
      {"materials", materials},
      {"lights",
       {{{"type", "point"}, {"position", {2.0, 3.0, 2.0}}, {"intensity", {20.0, 18.0, 16.0}}},
        {{"type", "directional"}, {"direction", {-0.3, -1.0, -0.2}}, {"irradiance", {0.5, 0.5, 0.6}}},
        {{"type", "sky"}, {"radiance", {0.1, 0.15, 0.2}}}}},
  };
}

// The smallest scene around one material "m" (an 8 x 8 view of a plane under a sky): for tests that parse a
// material's keys and effects without rendering.
inline nlohmann::json one_material_scene(const nlohmann::json& material) {
  return {{"camera", {{"position", {0, 1, 5}}, {"look_at", {0, 0, 0}}, {"width", 8}, {"height", 8}}},
          {"shapes", {{{"type", "plane"}, {"size", {4, 4}}, {"material", "m"}}}},
          {"materials", {{"m", material}}},
          {"lights", {{{"type", "sky"}, {"radiance", 1}}}}};
}

inline void write_json(const std::filesystem::path& path, const nlohmann::json& j) { std::ofstream(path) << j.dump(2); }

}  // namespace mbk::testing
