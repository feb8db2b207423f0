// The assets of several scenes as one batch, for `microbake bake SCENE...` and `microbake plan SCENE...`: each
// scene's plan (bake_plan.h) placed in its asset folder (the one folder given by --out-dir, or each scene's default
// folder), merged by output file, so that an asset several scenes call for is listed (and baked) once. Since names
// are content-addressed, two assets with the same path are the same bake.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "libbake/scene/bake_plan.h"

namespace mbk {

struct BatchScene {
  std::string name;  // the scene file as given on the command line
  Scene scene;
  std::filesystem::path asset_folder;
};

// Who calls for an asset: a scene's material's effect (kBaselineUse for the plain baseline).
struct BatchUse {
  std::string scene, material, effect;
};

struct BatchAsset {
  PlannedAsset planned;
  std::filesystem::path file;  // asset folder / file name; empty when an input is missing (see missing_input)
  std::vector<BatchUse> uses;  // scenes in the order given, then as plan_assets orders them
  // The first input file that does not exist, with what reads it; empty when every input exists.
  std::string missing_input;
};

// Loads nothing: the scenes are given loaded. Assets in order of first use.
std::vector<BatchAsset> plan_batch(const std::vector<BatchScene>& scenes);

// "scene.json: material 'a', effect 'glints'": where an asset is called for, for messages.
std::string use_text(const BatchUse& use);

// Loads the scenes named on a command line (load_scene), each with its asset folder: `out_dir` when not empty,
// else the scene's default_asset_folder.
std::vector<BatchScene> load_batch_scenes(const std::vector<std::string>& names, const std::filesystem::path& out_dir);

}  // namespace mbk
