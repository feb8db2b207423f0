// The registry of procedural normal-map generators (see generator.h).
#include "libbake/gen/generator.h"

#include "formats/error.h"

namespace mbk {

std::span<const GeneratorKind> generator_kinds() {
  static const GeneratorKind kinds[] = {
      {"bumps", "isotropic bumps (fractal gradient noise height field)", true, generate_bumps},
      {"brushed", "brushed metal: fine anisotropic streaks along u", true, generate_brushed},
      {"scratches", "sparse sharp V-groove scratches on a flat surface", true, generate_scratches},
      {"flakes", "metallic flakes: flat discs each with its own random tilt (piecewise constant)", false,
       generate_flakes},
      {"leather", "pebbled leather grain: rounded cells separated by creases", true, generate_leather},
      {"panels", "panel grid with 45-degree bevels, recessed insets and sharp creases", true, generate_panels},
  };
  return kinds;
}

const GeneratorKind* find_generator(std::string_view name) {
  for (const GeneratorKind& k : generator_kinds())
    if (k.name == name) return &k;
  return nullptr;
}

std::string generator_names() {
  std::string names;
  for (const GeneratorKind& k : generator_kinds()) names += (names.empty() ? "" : ", ") + std::string(k.name);
  return names;
}

NormalMap generate_normal_map(std::string_view kind, const MapSize& size, uint32_t seed, Progress& progress) {
  const GeneratorKind* g = find_generator(kind);
  if (!g)
    throw Error(ExitCode::bad_command_line,
                "unknown generator kind '" + std::string(kind) + "' (kinds: " + generator_names() + ")");
  if (size.width < 1 || size.height < 1 || size.width > kMaxNormalMapSide || size.height > kMaxNormalMapSide)
    throw Error(ExitCode::bad_command_line, "map size " + std::to_string(size.width) + "x" +
                                                std::to_string(size.height) + " outside 1.." +
                                                std::to_string(kMaxNormalMapSide) + " per side");
  progress.start("gen " + std::string(kind), size.height);
  NormalMap map = g->generate(size, seed, progress);
  progress.finish();
  return map;
}

}  // namespace mbk
