// Scene files: the JSON a user writes to describe what `render` draws and what `bake` prepares.
// Top-level keys: camera, shapes, materials, lights (docs/SCENES.md documents every key, its unit
// and its default). Reading is strict: an unknown key anywhere, a wrong type or an out-of-range value is an
// Error(invalid_input) naming its JSON path (e.g. "materials.brick.rougness"). Paths inside the scene
// (normal maps, environment maps) are relative to the scene file's folder.
//
// Units and conventions: lengths in scene units, angles in degrees, colours linear RGB, directions need
// not be normalised (they are normalised on load). World +Y is up for the environment map and the sphere's
// default pole. Every shape has a frame: `center`, `normal` (z, out of the surface; the sphere's pole) and
// `tangent` (x, the direction of +u; made orthogonal to the normal); the third axis is normal x tangent =
// +v, so the tangent frame is (x=+u, y=+v, z=out) as in libbake/image/normal_map.h.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "libbake/core/eigen.h"
#include "libbake/image/normal_map.h"
#include "libbake/scene/effect_use.h"

namespace mbk {

struct Camera {
  Vec3 position, look_at, up;
  double fov_y_degrees = 45;  // full vertical field of view
  uint32_t width = 0, height = 0;
};

enum class ShapeType { plane, sphere, bent_quad };

struct Shape {
  ShapeType type = ShapeType::plane;
  Vec3 center = Vec3::Zero();
  Vec3 normal = Vec3::UnitY();   // unit
  Vec3 tangent = Vec3::UnitX();  // unit, orthogonal to normal
  Vec2 size = Vec2::Ones();      // plane and bent_quad: extent along tangent (u) and along normal x tangent (v)
  double radius = 1;             // sphere
  double angle_degrees = 90;     // bent_quad: arc angle; > 0 bends away from the normal (convex), < 0 towards it
  Vec2 uv_scale = Vec2::Ones();  // texture repeats across the shape's [0, 1]^2 parameter square
  std::string material;
};

enum class Distribution { beckmann, ggx };
std::string distribution_name(Distribution d);

struct NormalMapRef {
  std::string path_as_written;   // as in the scene file
  std::filesystem::path path;    // resolved against the scene folder
  ConventionRequest convention;  // auto when the scene names none
  bool repair = false;
  NormalMapLoadOptions load_options() const;
};

struct Material {
  std::string name;
  Vec3 albedo = Vec3::Constant(0.5);  // Lambertian reflectance in [0, 1]
  Distribution distribution = Distribution::ggx;
  double roughness = 0.5;          // the microfacet alpha itself (no perceptual remapping)
  Vec3 f0 = Vec3::Constant(0.04);  // Fresnel reflectance at normal incidence (Schlick's approximation)
  std::optional<NormalMapRef> normal_map;
  std::vector<EffectUse> effects;  // registered in libbake/scene/effect_registry.h, in the order listed
};

struct PointLight {
  Vec3 position;
  Vec3 intensity;  // radiant intensity, W/sr per channel: irradiance intensity / d^2 at distance d
};
struct DirectionalLight {
  Vec3 direction;   // unit, the direction the light travels (from the light towards the scene)
  Vec3 irradiance;  // W/m^2 per channel on a surface facing the light
};
struct EnvironmentLight {
  std::string path_as_written;
  std::filesystem::path path;  // a lat-long image (EXR for HDR), projected to SH order 2 by the evaluator
  double scale = 1;
};
struct SkyLight {
  Vec3 radiance;  // constant radiance from every direction
};

struct Lights {
  std::vector<PointLight> points;
  std::vector<DirectionalLight> directionals;
  std::vector<EnvironmentLight> environments;
  std::vector<SkyLight> skies;
};

struct Scene {
  std::filesystem::path file;    // the scene file as given ("" when parsed from memory)
  std::filesystem::path folder;  // where relative paths start
  Camera camera;
  std::vector<Shape> shapes;
  std::map<std::string, Material> materials;
  Lights lights;
};

// Reads and checks a scene file. Error: io_failure when it cannot be read, invalid_input for malformed
// JSON or any problem in it, `where` = "<file>: <json path>".
Scene load_scene(const std::filesystem::path& file);
// The same from the file's bytes (`file` names it and its folder starts relative paths; nothing is read from disk).
Scene parse_scene_text(std::string_view text, const std::filesystem::path& file);
// The same from parsed JSON; relative paths resolve against `folder`; `where` = the JSON path.
Scene parse_scene(const nlohmann::json& json, const std::filesystem::path& folder);

}  // namespace mbk
