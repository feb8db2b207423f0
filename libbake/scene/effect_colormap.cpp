// The colour-map effects of [Heitz13] (Filtering Color Mapped Textures and Surfaces, I3D 2013), bake side:
//   colormap         C(f) of a driver f (a grayscale image or procedural noise) as the albedo (Sec. 4.2);
//   colormap-height  C(f + h) of a Gaussian microsurface's heights h on top of the driver, with Smith
//                    shadowing and the view/light-dependent height distribution (Sec. 5.1);
//   colormap-slope   C(offset + d . s) of a Gaussian microsurface's slopes s seen from the viewer (Sec. 5.2).
// They share their options (docs/SCENES.md documents them) and their
// assets: the prefiltered table of the colour map (kind `colormap`) and, when the driver is an image, its
// moment pyramid (kind `moments`). None needs the normal map. Evaluator side: libbake/eval/colormap_effect.h.
#include "formats/error.h"
#include "libbake/colormap/colormap_source.h"
#include "libbake/colormap/colormap_table.h"
#include "libbake/colormap/moment_pyramid.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk {
namespace {

enum class ColormapCase { texture, height, slope };

Parameter declare(const std::string& name, ParameterType type, double lo, double hi, nlohmann::json fallback,
                  const std::string& doc) {
  Parameter p;
  p.name = name;
  p.type = type;
  p.min = lo;
  p.max = hi;
  p.default_value = std::move(fallback);
  p.doc = doc;
  return p;
}

Parameter choice(const std::string& name, std::vector<std::string> choices, const std::string& doc) {
  Parameter p = declare(name, ParameterType::choice, 0, 0, choices.back(), doc);
  p.choices = std::move(choices);
  return p;
}

// The procedural driver: an object of {cells, octaves, gain, seed}, every key optional (libbake/gen/periodic_noise.h).
std::vector<Parameter> noise_fields() {
  return {declare("cells", ParameterType::size2, 1, 1u << 20, nlohmann::json::array({8, 8}),
                  "Noise lattice cells along u and v in one period"),
          declare("octaves", ParameterType::integer, 1, 16, 4, "fBm octaves"),
          declare("gain", ParameterType::number, 0, 1, 0.5, "Amplitude factor from one octave to the next"),
          declare("seed", ParameterType::integer, 0, 4294967295.0, 1, "Lattice gradient seed")};
}

// The keys of each case (docs/SCENES.md "Effects colormap, colormap-height, colormap-slope").
std::vector<Parameter> colormap_parameters(ColormapCase which) {
  std::vector<Parameter> p = {
      declare("colormap", ParameterType::file, 0, 0, nullptr, "The colour map: a gradient image or JSON stops"),
      effect_parameter("colormap", "table_size", "table_size"),
      effect_parameter("colormap", "sigma_max", "sigma_max"),
      choice("mode", {"naive", "filtered"}, "naive: C(mean), to compare; filtered: the table"),
      choice("combine", {"linear", "product"}, "How this material's colour-map effects combine ([Heitz13] Sec. 6)"),
      declare("weight", ParameterType::number, -1e3, 1e3, 1.0, "Weight in a linear combination")};
  p[4].default_value = "linear";
  if (which != ColormapCase::slope) {
    p.push_back(declare("driver", ParameterType::file, 0, 0, nullptr, "The driver image f (else noise)"));
    p.back().optional_file = true;
    p.push_back(declare("noise", ParameterType::object, 0, 0, nullptr,
                        "Procedural driver {cells, octaves, gain, seed} (the default without a driver)"));
    p.back().fields = noise_fields();
    p.push_back(declare("scale", ParameterType::number, -1e6, 1e6, 1.0, "f is mapped as offset + scale * f"));
    p.push_back(declare("offset", ParameterType::number, -1e6, 1e6, 0.0, "f is mapped as offset + scale * f"));
  }
  if (which == ColormapCase::height)
    p.push_back(declare("sigma_h", ParameterType::number, 1e-6, 1e6, 0.1, "Standard deviation of the heights"));
  if (which != ColormapCase::texture)
    p.push_back(declare("slope_sigma", ParameterType::number, 1e-3, 10, 0.3, "Standard deviation of the slopes"));
  if (which == ColormapCase::slope) {
    p.push_back(declare("direction_degrees", ParameterType::number, -360, 360, 0.0, "Direction d of the slope"));
    p.push_back(declare("offset", ParameterType::number, -1e6, 1e6, 0.5, "Added to d . s"));
  }
  return p;
}

// The noise object's declared keys, each given or defaulted.
nlohmann::json parse_noise(const Parameter& noise, const nlohmann::json* given, const std::string& path) {
  static const nlohmann::json kNone = nlohmann::json::object();
  JsonObjectReader n(given ? *given : kNone, path);
  nlohmann::json o = nlohmann::json::object();
  for (const Parameter& field : noise.fields) o[field.name] = read_parameter(n, field);
  n.reject_unknown_keys();
  return o;
}

// Reads the declared keys; the files are resolved, and the driver is an image or noise, not both.
EffectUse parse_colormap_options(JsonObjectReader& r, const std::filesystem::path& folder,
                                 const std::vector<Parameter>& parameters) {
  EffectUse use;
  nlohmann::json& o = use.options;
  for (const Parameter& p : parameters) {
    if (p.name == "colormap") {
      o[p.name] = effect_file_option(r, p.name, folder, use);
    } else if (p.name == "driver") {
      if (r.optional("driver")) o["driver"] = effect_file_option(r, "driver", folder, use);
    } else if (p.name == "noise") {
      const nlohmann::json* noise = r.optional("noise");
      if (noise && o.contains("driver"))
        throw Error(ExitCode::invalid_input, "give either 'driver' or 'noise', not both", r.child("noise"));
      if (!o.contains("driver")) o["noise"] = parse_noise(p, noise, r.child("noise"));
    } else if (p.name == "weight") {
      if (r.optional("weight") && o["combine"] == "product")
        throw Error(ExitCode::invalid_input, "a product combination takes no weights", r.child("weight"));
      o[p.name] = read_parameter(r, p);
    } else {
      o[p.name] = read_parameter(r, p);
    }
  }
  o["sigma_max"] = float(o["sigma_max"].get<double>());  // as the asset records it
  return use;
}

std::vector<AssetRecipe> colormap_assets(const EffectUse& use) {
  const std::filesystem::path map = use.files.at("colormap");
  ColormapTableOptions table;
  table.width = use.options["table_size"][0];
  table.height = use.options["table_size"][1];
  table.sigma_max = use.options["sigma_max"];
  nlohmann::json parameters = {{"width", table.width}, {"height", table.height}};
  if (table.sigma_max > 0) parameters["sigma_max"] = table.sigma_max;
  std::vector<AssetRecipe> recipes{{"colormap",
                                    parameters,
                                    {{map, std::nullopt}},
                                    [map, table](Progress& progress) {
                                      const LoadedColormap source = load_colormap_source(map, ColorEncoding::automatic);
                                      ColormapTableOptions options = table;
                                      options.mean_min = source.domain_min;
                                      options.mean_max = source.domain_max;
                                      return colormap_asset_writer(bake_colormap_table(source.curve, options, progress),
                                                                   source.record, source.encoding);
                                    },
                                    use.options}};
  if (use.files.count("driver")) {
    const std::filesystem::path driver = use.files.at("driver");
    recipes.push_back({"moments", nlohmann::json::object(), {{driver, std::nullopt}}, [driver](Progress&) {
                         const Driver d = load_driver(driver, 0);
                         return moments_asset_writer(build_moment_pyramid(d), d);
                       }});
  }
  return recipes;
}

EffectInfo colormap_effect_of(ColormapCase which) {
  EffectInfo e;
  e.needs_normal_map = false;
  e.sets_albedo = true;
  e.parameters = colormap_parameters(which);
  e.parse_options = [parameters = e.parameters](JsonObjectReader& r, const std::filesystem::path& folder) {
    return parse_colormap_options(r, folder, parameters);
  };
  e.assets = [](const Material&, const EffectUse& use) { return colormap_assets(use); };
  return e;
}

}  // namespace

EffectInfo colormap_effect() {
  EffectInfo e = colormap_effect_of(ColormapCase::texture);
  e.name = "colormap";
  e.summary = "albedo = colour map of a driver (image or noise), filtered over the footprint ([Heitz13] Sec. 4)";
  return e;
}

EffectInfo colormap_height_effect() {
  EffectInfo e = colormap_effect_of(ColormapCase::height);
  e.name = "colormap-height";
  e.summary = "albedo = colour map of a Gaussian microsurface's heights on the driver, with shadowing ([Heitz13] 5.1)";
  return e;
}

EffectInfo colormap_slope_effect() {
  EffectInfo e = colormap_effect_of(ColormapCase::slope);
  e.name = "colormap-slope";
  e.summary = "albedo = colour map of a Gaussian microsurface's slopes, as seen from the viewer ([Heitz13] 5.2)";
  return e;
}

}  // namespace mbk
