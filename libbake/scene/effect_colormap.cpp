// The colour-map effects of [Heitz13] (Filtering Color Mapped Textures and Surfaces, I3D 2013), bake side:
//   colormap         C(f) of a driver f (a grayscale image or procedural noise) as the albedo (Sec. 4.2);
//   colormap-height  C(f + h) of a Gaussian microsurface's heights h on top of the driver, with Smith
//                    shadowing and the view/light-dependent height distribution (Sec. 5.1);
//   colormap-slope   C(offset + d . s) of a Gaussian microsurface's slopes s seen from the viewer (Sec. 5.2).
// They share their options (README "Scene files" documents them) and their
// assets: the prefiltered table of the colour map (kind `colormap`) and, when the driver is an image, its
// moment pyramid (kind `moments`). None needs the normal map. Evaluator side: libbake/eval/colormap_effect.h.
#include "formats/error.h"
#include "libbake/colormap/colormap_source.h"
#include "libbake/colormap/colormap_table.h"
#include "libbake/colormap/moment_pyramid.h"
#include "libbake/scene/effect_registry.h"

namespace mbk {
namespace {

enum class ColormapCase { texture, height, slope };

// The options every case reads: the colour map, its table and the mode.
void parse_common(JsonObjectReader& r, const std::filesystem::path& folder, EffectUse& use) {
  nlohmann::json& o = use.options;
  o["colormap"] = effect_file_option(r, "colormap", folder, use);
  std::array<uint32_t, 2> size{kColormapDefaultSide, kColormapDefaultSide};
  if (const auto* v = r.optional("table_size")) {
    if (!v->is_array() || v->size() != 2)
      throw Error(ExitCode::invalid_input, "expected [width, height]", r.child("table_size"));
    for (size_t i = 0; i < 2; ++i)
      size[i] = json_uint((*v)[i], json_index_path(r.child("table_size"), i), kColormapMinSide, kColormapMaxSide);
  }
  o["table_size"] = size;
  o["sigma_max"] = 0.0;  // 0: the default, half the colour map's domain
  if (const auto* v = r.optional("sigma_max")) o["sigma_max"] = float(json_number(*v, r.child("sigma_max"), 0, 1e6));
  o["mode"] = "filtered";
  if (const auto* v = r.optional("mode")) o["mode"] = json_choice(*v, r.child("mode"), {"naive", "filtered"});
  // Sec. 6: how the colour-map effects of one material combine (libbake/eval/colormap_effect.h).
  o["combine"] = "linear";
  if (const auto* v = r.optional("combine")) o["combine"] = json_choice(*v, r.child("combine"), {"linear", "product"});
  o["weight"] = 1.0;
  if (const auto* v = r.optional("weight")) {
    if (o["combine"] == "product")
      throw Error(ExitCode::invalid_input, "a product combination takes no weights", r.child("weight"));
    o["weight"] = json_number(*v, r.child("weight"), -1e3, 1e3);
  }
}

// The driver f: an image (first channel) or procedural noise, mapped as offset + scale * f.
void parse_driver(JsonObjectReader& r, const std::filesystem::path& folder, EffectUse& use) {
  nlohmann::json& o = use.options;
  const auto* noise = r.optional("noise");
  if (r.optional("driver")) {
    if (noise) throw Error(ExitCode::invalid_input, "give either 'driver' or 'noise', not both", r.child("noise"));
    o["driver"] = effect_file_option(r, "driver", folder, use);
  } else {
    static const nlohmann::json kDefaults = nlohmann::json::object();
    JsonObjectReader n(noise ? *noise : kDefaults, r.child("noise"));
    std::array<uint32_t, 2> cells{8, 8};
    if (const auto* v = n.optional("cells")) {
      if (!v->is_array() || v->size() != 2)
        throw Error(ExitCode::invalid_input, "expected [cells_u, cells_v]", n.child("cells"));
      for (size_t i = 0; i < 2; ++i) cells[i] = json_uint((*v)[i], json_index_path(n.child("cells"), i), 1, 1u << 20);
    }
    const auto* octaves = n.optional("octaves");
    const auto* gain = n.optional("gain");
    const auto* seed = n.optional("seed");
    o["noise"] = {{"cells", cells},
                  {"octaves", octaves ? json_uint(*octaves, n.child("octaves"), 1, 16) : 4u},
                  {"gain", gain ? json_number(*gain, n.child("gain"), 0, 1) : 0.5},
                  {"seed", seed ? json_uint(*seed, n.child("seed"), 0, 0xffffffffu) : 1u}};
    n.reject_unknown_keys();
  }
  const auto* scale = r.optional("scale");
  const auto* offset = r.optional("offset");
  o["scale"] = scale ? json_number(*scale, r.child("scale"), -1e6, 1e6) : 1.0;
  o["offset"] = offset ? json_number(*offset, r.child("offset"), -1e6, 1e6) : 0.0;
}

double slope_sigma_option(JsonObjectReader& r) {
  const auto* v = r.optional("slope_sigma");
  return v ? json_number(*v, r.child("slope_sigma"), 1e-3, 10) : 0.3;
}

std::vector<AssetRecipe> colormap_assets(const EffectUse& use) {
  const std::filesystem::path map = use.files.at("colormap");
  ColormapTableOptions table;
  table.width = use.options["table_size"][0];
  table.height = use.options["table_size"][1];
  table.sigma_max = use.options["sigma_max"];
  nlohmann::json parameters = {{"width", table.width}, {"height", table.height}};
  if (table.sigma_max > 0) parameters["sigma_max"] = table.sigma_max;
  std::vector<AssetRecipe> recipes{{"colormap", parameters, {{map, std::nullopt}}, [map, table](Progress& progress) {
                                      const LoadedColormap source = load_colormap_source(map, ColorEncoding::automatic);
                                      ColormapTableOptions options = table;
                                      options.mean_min = source.domain_min;
                                      options.mean_max = source.domain_max;
                                      return colormap_asset_writer(bake_colormap_table(source.curve, options, progress),
                                                                   source.record, source.encoding);
                                    }}};
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
  e.parse_options = [which](JsonObjectReader& r, const std::filesystem::path& folder) {
    EffectUse use;
    parse_common(r, folder, use);
    if (which != ColormapCase::slope) parse_driver(r, folder, use);
    if (which == ColormapCase::height) {
      const auto* v = r.optional("sigma_h");
      use.options["sigma_h"] = v ? json_number(*v, r.child("sigma_h"), 1e-6, 1e6) : 0.1;
      use.options["slope_sigma"] = slope_sigma_option(r);
    }
    if (which == ColormapCase::slope) {
      use.options["slope_sigma"] = slope_sigma_option(r);
      const auto* d = r.optional("direction_degrees");
      const auto* offset = r.optional("offset");
      use.options["direction_degrees"] = d ? json_number(*d, r.child("direction_degrees"), -360, 360) : 0.0;
      use.options["offset"] = offset ? json_number(*offset, r.child("offset"), -1e6, 1e6) : 0.5;
    }
    return use;
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
