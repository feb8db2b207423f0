// Scene file parsing (see scene.h): strict keys, typed values, ranges, and paths resolved against the
// scene's folder.
#include "libbake/scene/scene.h"

#include <Eigen/Geometry>  // cross products

#include <cmath>

#include "formats/atomic_file.h"
#include "formats/error.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/json_fields.h"

namespace mbk {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw Error(ExitCode::invalid_input, what, path);
}

constexpr uint32_t kMaxImageSide = 16384;
constexpr double kHuge = 1e30;
// Roughness (alpha) range: at alpha = 1 the lobe is already nearly uniform; below 0.001 a point light's
// highlight is a spark far smaller than any pixel, which no sampling resolves.
constexpr double kMinRoughness = 0.001, kMaxRoughness = 1.0;

fs::path resolve(const fs::path& folder, const std::string& written) {
  const fs::path p(written);
  return (p.is_absolute() ? p : folder / p).lexically_normal();
}

Camera parse_camera(JsonObjectReader r) {
  Camera c;
  c.position = json_vec3(r.required("position"), r.child("position"));
  c.look_at = json_vec3(r.required("look_at"), r.child("look_at"));
  c.up = Vec3::UnitY();
  if (const auto* v = r.optional("up")) c.up = json_direction(*v, r.child("up"));
  if (const auto* v = r.optional("fov_y")) c.fov_y_degrees = json_number(*v, r.child("fov_y"), 0.01, 179);
  c.width = json_uint(r.required("width"), r.child("width"), 1, kMaxImageSide);
  c.height = json_uint(r.required("height"), r.child("height"), 1, kMaxImageSide);
  r.reject_unknown_keys();
  const Vec3 forward = c.look_at - c.position;
  if (!(forward.norm() > 1e-12)) fail("look_at equals position", r.child("look_at"));
  // Below this sine the camera's right vector (forward x up) is too short to normalise reliably.
  if (forward.normalized().cross(c.up).norm() < 1e-6) fail("up is parallel to the viewing direction", r.child("up"));
  return c;
}

Shape parse_shape(JsonObjectReader r) {
  Shape s;
  const std::string type = json_choice(r.required("type"), r.child("type"), {"plane", "sphere", "bent_quad"});
  s.type = type == "plane" ? ShapeType::plane : type == "sphere" ? ShapeType::sphere : ShapeType::bent_quad;
  if (const auto* v = r.optional("center")) s.center = json_vec3(*v, r.child("center"));
  if (const auto* v = r.optional("normal")) s.normal = json_direction(*v, r.child("normal"));
  if (const auto* v = r.optional("tangent")) s.tangent = json_direction(*v, r.child("tangent"));
  const Vec3 t = s.tangent - s.tangent.dot(s.normal) * s.normal;
  // A tangent within ~0.06 degrees of the normal leaves an orthogonal part dominated by rounding.
  if (t.norm() < 1e-3) fail("tangent is parallel to normal", r.child("tangent"));
  s.tangent = t.normalized();
  if (const auto* v = r.optional("uv_scale")) s.uv_scale = json_vec2(*v, r.child("uv_scale"), 1e-6, 1e6);
  s.material = json_string(r.required("material"), r.child("material"));
  if (s.type == ShapeType::sphere) {
    s.radius = json_number(r.required("radius"), r.child("radius"), 1e-9, kHuge);
  } else {
    s.size = json_vec2(r.required("size"), r.child("size"), 1e-9, kHuge);
  }
  if (s.type == ShapeType::bent_quad) {
    s.angle_degrees = json_number(r.required("angle"), r.child("angle"), -360, 360);
    // The bend radius is size.u / angle: at |angle| -> 0 it diverges; a flat rectangle is a plane.
    if (std::abs(s.angle_degrees) < 0.01)
      fail("|angle| must be at least 0.01 degrees (use a plane for a flat rectangle)", r.child("angle"));
  }
  r.reject_unknown_keys();
  return s;
}

NormalMapRef parse_normal_map(JsonObjectReader r, const fs::path& folder) {
  NormalMapRef m;
  m.path_as_written = json_string(r.required("path"), r.child("path"));
  if (m.path_as_written.empty()) fail("empty path", r.child("path"));
  m.path = resolve(folder, m.path_as_written);
  if (const auto* v = r.optional("convention")) {
    // The same names as the commands' --convention: auto, +Y/opengl or -Y/directx, any case.
    const std::string name = json_string(*v, r.child("convention"));
    try {
      m.convention = parse_convention_request(name);
    } catch (const Error& e) {
      fail(e.what(), r.child("convention"));
    }
  }
  if (const auto* v = r.optional("repair")) m.repair = json_bool(*v, r.child("repair"));
  r.reject_unknown_keys();
  return m;
}

// One entry of a material's `effects`: a name, or an object with "name" and the effect's options.
EffectUse parse_effect(const nlohmann::json& v, const std::string& at, const Material& m, const fs::path& folder) {
  static const nlohmann::json kNoOptions = nlohmann::json::object();
  JsonObjectReader options(v.is_object() ? v : kNoOptions, at);
  const std::string name =
      v.is_object() ? json_string(options.required("name"), options.child("name")) : json_string(v, at);
  const EffectInfo* effect = find_effect(name);
  if (!effect) fail("unknown effect '" + name + "' (known effects: " + known_effect_names() + ")", at);
  for (const auto& e : m.effects) {
    if (e.name == name) fail("effect '" + name + "' is listed twice", at);
    if (find_effect(e.name)->sets_albedo && !effect->sets_albedo)
      fail("effect '" + name + "' must be listed before the colour-map effects ('" + e.name +
               "' colours the shading built before it, which '" + name + "' would replace)",
           at);
  }
  if (effect->needs_normal_map && !m.normal_map) fail("effect '" + name + "' needs a normal_map in this material", at);
  EffectUse use;
  if (effect->parse_options)
    use = effect->parse_options(options, folder);
  else
    for (const Parameter& p : effect->parameters) use.options[p.name] = read_parameter(options, p);
  options.reject_unknown_keys();  // only the declared keys
  use.name = name;
  return use;
}

Material parse_material(const std::string& name, JsonObjectReader r, const fs::path& folder) {
  Material m;
  m.name = name;
  if (const auto* v = r.optional("albedo")) m.albedo = json_rgb(*v, r.child("albedo"), 0, 1);
  if (const auto* v = r.optional("specular")) {
    JsonObjectReader s(*v, r.child("specular"));
    if (const auto* d = s.optional("distribution"))
      m.distribution = json_choice(*d, s.child("distribution"), {"beckmann", "ggx"}) == "ggx" ? Distribution::ggx
                                                                                              : Distribution::beckmann;
    if (const auto* a = s.optional("roughness"))
      m.roughness = json_number(*a, s.child("roughness"), kMinRoughness, kMaxRoughness);
    if (const auto* f = s.optional("f0")) m.f0 = json_rgb(*f, s.child("f0"), 0, 1);
    s.reject_unknown_keys();
  }
  if (const auto* v = r.optional("normal_map"))
    m.normal_map = parse_normal_map(JsonObjectReader(*v, r.child("normal_map")), folder);
  if (const auto* v = r.optional("effects")) {
    const std::string path = r.child("effects");
    if (!v->is_array()) fail("expected an array of effects (names or {\"name\": ..., options} objects)", path);
    for (size_t i = 0; i < v->size(); ++i)
      m.effects.push_back(parse_effect((*v)[i], json_index_path(path, i), m, folder));
  }
  r.reject_unknown_keys();
  return m;
}

void parse_light(JsonObjectReader r, const fs::path& folder, Lights& lights) {
  const std::string type =
      json_choice(r.required("type"), r.child("type"), {"point", "directional", "environment", "sky"});
  if (type == "point") {
    lights.points.push_back({json_vec3(r.required("position"), r.child("position")),
                             json_rgb(r.required("intensity"), r.child("intensity"), 0, kHuge)});
  } else if (type == "directional") {
    lights.directionals.push_back({json_direction(r.required("direction"), r.child("direction")),
                                   json_rgb(r.required("irradiance"), r.child("irradiance"), 0, kHuge)});
  } else if (type == "environment") {
    EnvironmentLight e;
    e.path_as_written = json_string(r.required("path"), r.child("path"));
    if (e.path_as_written.empty()) fail("empty path", r.child("path"));
    e.path = resolve(folder, e.path_as_written);
    if (const auto* v = r.optional("scale")) e.scale = json_number(*v, r.child("scale"), 0, kHuge);
    lights.environments.push_back(e);
  } else {
    lights.skies.push_back({json_rgb(r.required("radiance"), r.child("radiance"), 0, kHuge)});
  }
  r.reject_unknown_keys();
}

}  // namespace

std::string distribution_name(Distribution d) { return d == Distribution::ggx ? "ggx" : "beckmann"; }

NormalMapLoadOptions NormalMapRef::load_options() const {
  NormalMapLoadOptions o;
  o.convention = convention;
  o.invalid = repair ? InvalidTexelPolicy::repair : InvalidTexelPolicy::error;
  o.repair_hint = "\"repair\": true in the material's normal_map";
  return o;
}

Scene parse_scene(const nlohmann::json& json, const fs::path& folder) {
  Scene scene;
  scene.folder = folder;
  JsonObjectReader top(json, "");
  scene.camera = parse_camera(JsonObjectReader(top.required("camera"), "camera"));

  const nlohmann::json& materials = top.required("materials");
  if (!materials.is_object()) fail("expected an object of named materials", "materials");
  for (auto it = materials.begin(); it != materials.end(); ++it) {
    const std::string path = json_child_path("materials", it.key());
    if (it.key().empty()) fail("empty material name", path);
    scene.materials.emplace(it.key(), parse_material(it.key(), JsonObjectReader(it.value(), path), folder));
  }

  const nlohmann::json& shapes = top.required("shapes");
  if (!shapes.is_array()) fail("expected an array of shapes", "shapes");
  for (size_t i = 0; i < shapes.size(); ++i) {
    const std::string path = json_index_path("shapes", i);
    scene.shapes.push_back(parse_shape(JsonObjectReader(shapes[i], path)));
    const std::string& name = scene.shapes.back().material;
    if (!scene.materials.count(name)) {
      std::string known;
      for (const auto& [k, _] : scene.materials) known += (known.empty() ? "" : ", ") + k;
      fail("unknown material '" + name + "' (materials: " + (known.empty() ? "none" : known) + ")",
           json_child_path(path, "material"));
    }
  }

  const nlohmann::json& lights = top.required("lights");
  if (!lights.is_array()) fail("expected an array of lights", "lights");
  for (size_t i = 0; i < lights.size(); ++i)
    parse_light(JsonObjectReader(lights[i], json_index_path("lights", i)), folder, scene.lights);

  top.reject_unknown_keys();
  return scene;
}

Scene load_scene(const fs::path& file) {
  const std::vector<uint8_t> bytes = read_file_bytes(file);
  return parse_scene_text(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), file);
}

Scene parse_scene_text(std::string_view text, const fs::path& file) {
  const nlohmann::json json = parse_json_strict(text, file.string());
  fs::path folder = file.parent_path();
  if (folder.empty()) folder = ".";
  try {
    Scene scene = parse_scene(json, folder);
    scene.file = file;
    return scene;
  } catch (const Error& e) {
    throw Error(e.code(), e.what(), file.string() + ": " + (e.where().empty() ? "(top level)" : e.where()));
  }
}

}  // namespace mbk
