// Every technique's parameters (see technique_parameters.h). The docs are the commands' help lines and the README's
// option tables; limits come from the techniques' own headers.
#include "libbake/scene/technique_parameters.h"

#include <stdexcept>

#include "formats/colormap_layout.h"
#include "formats/histogram_layout.h"
#include "formats/lut_layout.h"
#include "formats/rmq_layout.h"
#include "libbake/core/sh_basis.h"

namespace mbk {
namespace {

constexpr double kAnyUint32 = 4294967295.0;

Parameter integer(std::string name, double lo, double hi, nlohmann::json fallback, std::string doc) {
  Parameter p;
  p.name = name;
  for (char& c : name)
    if (c == '_') c = '-';
  p.option = "--" + name;
  p.min = lo;
  p.max = hi;
  p.default_value = std::move(fallback);
  p.doc = std::move(doc);
  return p;
}

Parameter number(std::string name, double lo, double hi, nlohmann::json fallback, std::string doc) {
  Parameter p = integer(std::move(name), lo, hi, std::move(fallback), std::move(doc));
  p.type = ParameterType::number;
  return p;
}

Parameter choice(std::string name, std::vector<std::string> choices, std::string fallback, std::string doc) {
  Parameter p = integer(std::move(name), 0, 0, std::move(fallback), std::move(doc));
  p.type = ParameterType::choice;
  p.choices = std::move(choices);
  return p;
}

Parameter command_line_only(Parameter p) {
  p.in_scenes = false;
  return p;
}

std::vector<TechniqueSchema> declare_schemas() {
  Parameter patch = integer("patch", 1, kRmqMaxPatch, nullptr,
                            "Largest stored square side P in texels, not above the example's smaller side; levels "
                            "0..log2(P) are stored (default 64, 7 levels, or the largest power of two that fits a "
                            "smaller example)");
  patch.power_of_two = true;
  Parameter bits = integer("bits", 8, 16, 16, "Bits per stored bound: 16 (8 bytes per entry) or 8 (4 bytes)");
  bits.allowed = {8, 16};
  Parameter table_size =
      integer("table_size", kColormapMinSide, kColormapMaxSide, {kColormapDefaultSide, kColormapDefaultSide},
              "Table size: W mean samples x H standard-deviation samples");
  table_size.type = ParameterType::size2;
  table_size.option = "--size";
  Parameter level = integer("level", 0, 40, nullptr,
                            "Synthesis level T: a texel of the root's coarsest stack level is 2^T pixels wide there, a "
                            "texel of the root itself 2^(T - L)");
  level.in_scenes = false;
  level.required = true;
  return {
      {"mip", {}},
      {"lut",
       {integer("size", kLutMinSize, kLutMaxSize, kLutDefaultSize,
                "Grid points per axis: knots of G at this many x and this many z positions per channel, plus the "
                "example's repeated values exactly; 128 is the paper's table size")}},
      {"rmq", {patch, bits}},
      {"sh",
       {integer("order", 0, kMaxShOrder, kShDefaultOrder,
                "Highest SH band L ((L+1)^2 coefficients per texel); the paper shades with L ~ sqrt(4 s) for a "
                "Blinn-Phong exponent s"),
        choice("precision", {"f16", "f32"}, "f16", "Element type of the coefficient levels"),
        choice("window", {"none", "hann", "lanczos"}, "none",
               "Window the evaluator applies per band against ringing (stored, not baked into the coefficients)")}},
      {"vmf",
       {integer("lobes", 1, kVmfMaxLobes, kVmfDefaultLobes, "vMF lobes per texel (J)"),
        number("align", 0.0, 1e6, 0.0,
               "Coherence weight C of [Han07] Eq. 7.26 (0: lobes are only ordered to match their neighbours)"),
        number("tolerance", 1e-15, 1.0, 1e-6,
               "EM stops when the mean log-likelihood per normal rises by less than this"),
        integer("max_iterations", 1, 100000, kVmfDefaultMaxIterations, "EM iterations at most per texel and start")}},
      {"crease",
       {integer("smooth_iterations", 0, kCreaseMaxSmoothIterations, kCreaseDefaultSmoothIterations,
                "Constrained Laplacian smoothing iterations of the gradient map"),
        number("band", 1e-6, 1e6, kCreaseDefaultBand,
               "Texels around the curves where the distance map is exact by brute force (beyond: nearest-segment "
               "propagation)")}},
      {"colormap",
       {table_size,
        number("sigma_max", 0.0, 1e6, 0.0,
               "Largest standard deviation tabulated (driver units); 0: half the colour map's domain"),
        command_line_only(choice("encoding", {"auto", "srgb", "linear"}, "auto",
                                 "Colour encoding of the colour map: auto (integer images and JSON stops are sRGB, "
                                 "float images linear), srgb or linear (scenes: auto)"))}},
      {"moments",
       {command_line_only(integer("channel", 0, kAnyUint32, 0, "Image channel holding f (0 = the first; scenes: 0)"))}},
      {"graph",
       {command_line_only(integer("candidates", 1, 16, 2, "k-coherence candidates per stack texel, K (the thesis: 2)")),
        command_line_only(
            integer("pca_components", 1, 100, 8,
                    "Principal components of the 5 x 5 neighbourhoods the candidate search matches in"))}},
      {"synth",
       {level, command_line_only(integer("seed", 0, kAnyUint32, 1, "Jitter hash seed")),
        command_line_only(integer("passes", 1, 8, 2, "Correction passes per level (4 sub-passes each)"))}},
      {"histogram",
       {command_line_only(choice("method", {"neural", "exact"}, "neural",
                                 "How the binned P-NDF is stored: neural, a feature pyramid and small MLPs trained "
                                 "on the CPU ([Shah24] Sec. 4.2); exact, integral images of per-bin counts ([GGN18])")),
        command_line_only(integer("theta_bins", 1, kHistogramMaxThetaBins, kHistogramDefaultThetaBins,
                                  "Adaptive theta bins requested, K (1-D k-means centres; fewer when the map has "
                                  "fewer distinct theta values)")),
        command_line_only(
            integer("phi_bins", 1, kHistogramMaxPhiBins, kHistogramDefaultPhiBins, "Uniform phi bins, N")),
        command_line_only(choice("theta_binning", {"adaptive", "uniform"}, "adaptive",
                                 "Theta bin centres: adaptive (1-D k-means of the map's normals, [Shah24] Sec. 4.1) "
                                 "or uniform (equal widths, the baseline of [Shah24] Fig. 3)")),
        command_line_only(integer("features", 1, kNeuralHistogramMaxFeatures, kNeuralHistogramDefaultFeatures,
                                  "Neural: features per texel of the feature pyramid, F")),
        command_line_only(integer("iterations", 1, kNeuralHistogramMaxIterations, kNeuralHistogramDefaultIterations,
                                  "Neural: training iterations (Adam steps)")),
        command_line_only(integer("batch", 1, kNeuralHistogramMaxBatch, kNeuralHistogramDefaultBatch,
                                  "Neural: random footprints per training iteration")),
        command_line_only(integer("seed", 0, kAnyUint32, 1,
                                  "Neural: training seed (initial weights and footprints; with the input's content "
                                  "hash)"))}},
  };
}

}  // namespace

std::span<const TechniqueSchema> technique_schemas() {
  static const std::vector<TechniqueSchema> schemas = declare_schemas();
  return schemas;
}

const TechniqueSchema& technique_schema(std::string_view technique) {
  for (const TechniqueSchema& s : technique_schemas())
    if (s.technique == technique) return s;
  throw std::out_of_range("no technique '" + std::string(technique) + "'");
}

Parameter effect_parameter(std::string_view technique, std::string_view name, std::string_view key) {
  Parameter p = technique_schema(technique).at(name);
  p.source = std::string(technique) + "." + std::string(name);
  p.name = key;
  p.option.clear();
  return p;
}

std::vector<Parameter> effect_parameters(std::string_view technique) {
  std::vector<Parameter> keys;
  for (const Parameter& p : technique_schema(technique).parameters)
    if (p.in_scenes) keys.push_back(effect_parameter(technique, p.name, p.name));
  return keys;
}

ShBakeOptions sh_bake_options(const nlohmann::json& parameters) {
  return {parameters.at("order").get<int>(), parse_precision(parameters.at("precision").get<std::string>()),
          parse_window(parameters.at("window").get<std::string>())};
}

VmfBakeOptions vmf_bake_options(const nlohmann::json& parameters) {
  VmfBakeOptions bake;
  bake.lobes = parameters.at("lobes").get<int>();
  bake.em.align = parameters.at("align").get<double>();
  bake.em.tolerance = parameters.at("tolerance").get<double>();
  bake.em.max_iterations = parameters.at("max_iterations").get<int>();
  return bake;
}

HistogramBakeOptions histogram_bake_options(const nlohmann::json& parameters) {
  return {parameters.at("theta_bins").get<uint32_t>(), parameters.at("phi_bins").get<uint32_t>(),
          parameters.at("theta_binning") == "uniform" ? ThetaBinning::uniform : ThetaBinning::adaptive};
}

NeuralHistogramBakeOptions neural_histogram_bake_options(const nlohmann::json& parameters) {
  NeuralHistogramBakeOptions options;
  options.bins = histogram_bake_options(parameters);
  options.features = parameters.at("features").get<uint32_t>();
  options.iterations = parameters.at("iterations").get<uint32_t>();
  options.batch = parameters.at("batch").get<uint32_t>();
  options.seed = parameters.at("seed").get<uint64_t>();
  return options;
}

CreaseBakeOptions crease_bake_options(const nlohmann::json& parameters) {
  CreaseBakeOptions bake;
  bake.smooth_iterations = parameters.at("smooth_iterations").get<uint32_t>();
  bake.band = parameters.at("band").get<double>();
  return bake;
}

}  // namespace mbk
