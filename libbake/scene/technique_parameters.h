// The parameters of every technique, declared once (parameter_schema.h): the options of `microbake <technique>` and
// the keys of the scene effects that bake it. Each technique's schema is named after its command and asset kind;
// mip has no parameters. The conversions from canonical parameter values (JSON, as read_parameter and the command
// line produce them) to a baker's options live here too, so that a command and an effect bake alike.
#pragma once

#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "libbake/crease/crease_asset.h"
#include "libbake/filter/sh_asset.h"
#include "libbake/filter/vmf_pyramid.h"
#include "libbake/histogram/histogram_bake.h"
#include "libbake/histogram/neural_histogram_bake.h"
#include "libbake/scene/parameter_schema.h"

namespace mbk {

// mip, lut, rmq, sh, vmf, crease, colormap, moments, graph, synth, histogram.
std::span<const TechniqueSchema> technique_schemas();
// The schema of one technique; std::out_of_range for an unknown name (a programming error).
const TechniqueSchema& technique_schema(std::string_view technique);
// A technique's parameter as an effect key of another name, default or narrower range (Parameter::source set).
Parameter effect_parameter(std::string_view technique, std::string_view name, std::string_view key);
// Every parameter of a technique that scenes may set, as effect keys of the same names.
std::vector<Parameter> effect_parameters(std::string_view technique);

// Canonical parameter values (an object with every parameter of the technique) -> the baker's options.
ShBakeOptions sh_bake_options(const nlohmann::json& parameters);
VmfBakeOptions vmf_bake_options(const nlohmann::json& parameters);
CreaseBakeOptions crease_bake_options(const nlohmann::json& parameters);
HistogramBakeOptions histogram_bake_options(const nlohmann::json& parameters);
NeuralHistogramBakeOptions neural_histogram_bake_options(const nlohmann::json& parameters);

}  // namespace mbk
