// Up-to-date checks of baked assets against the current inputs (see asset_freshness.h).
#include "libbake/scene/asset_freshness.h"

#include <algorithm>

#include "formats/asset.h"
#include "formats/version.h"
#include "formats/error.h"

namespace mbk {
namespace {

AssetFreshness stale(std::string why) { return {AssetState::stale, std::move(why)}; }

std::string text_of(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

}  // namespace

AssetFreshness check_asset_freshness(const PlannedAsset& planned, const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return {AssetState::missing, "no file yet"};
  std::optional<Asset> asset;
  try {
    asset.emplace(Asset::open(file));
  } catch (const Error& e) {
    return stale("existing file is not a valid asset: " + std::string(e.what()));
  }
  const AssetRecipe& recipe = planned.recipe;
  if (asset->kind().name != recipe.kind)
    return stale("existing file is a '" + std::string(asset->kind().name) + "' asset, not '" + recipe.kind + "'");

  // A new microbake may bake differently: rebuild what an older (or newer) version baked.
  const std::string baked_by = asset->metadata()["producer"]["version"].get<std::string>();
  if (baked_by != microbake_version())
    return stale("baked by microbake " + baked_by + ", this is " + microbake_version());

  const nlohmann::json& inputs = asset->metadata()["inputs"];
  if (!inputs.is_array() || inputs.size() != recipe.inputs.size())
    return stale("existing file records " + std::to_string(inputs.is_array() ? inputs.size() : 0) +
                 " inputs, the effect bakes from " + std::to_string(recipe.inputs.size()));
  std::string hashes;
  for (size_t i = 0; i < inputs.size(); ++i) {
    const BakeInput& planned_in = recipe.inputs[i];
    const nlohmann::json in = inputs[i].is_object() ? inputs[i] : nlohmann::json::object();
    if (!std::filesystem::exists(planned_in.path, ec)) continue;
    const std::string now = file_content_hash(planned_in.path);
    hashes += (hashes.empty() ? "" : ", ") + now;
    const nlohmann::json recorded_hash = in.value("content_hash", nlohmann::json());
    if (recorded_hash != now)
      return stale("input " + planned_in.path.filename().string() + " changed (recorded " + text_of(recorded_hash) +
                   ", now " + now + ")");
    if (!planned_in.normal_map) continue;
    // The convention asked for: what auto decides is a function of the input's bytes, compared above.
    const std::string convention = convention_request_name(planned_in.normal_map->convention);
    if (in.value("convention_requested", nlohmann::json()) != convention)
      return stale("normal-map convention changed (recorded " +
                   text_of(in.value("convention_requested", nlohmann::json())) + ", now " + convention + ")");
    const std::string policy = planned_in.normal_map->repair ? "repair" : "error";
    if (in.value("invalid_policy", nlohmann::json()) != policy)
      return stale("invalid-texel policy changed (recorded " + text_of(in.value("invalid_policy", nlohmann::json())) +
                   ", now " + policy + ")");
  }

  const nlohmann::json& params = asset->metadata()["parameters"];
  for (auto it = recipe.parameters.begin(); it != recipe.parameters.end(); ++it) {
    const nlohmann::json recorded = params.is_object() ? params.value(it.key(), nlohmann::json()) : nlohmann::json();
    if (recorded != it.value())
      return stale("parameter '" + it.key() + "' changed (recorded " + recorded.dump() + ", now " + it.value().dump() +
                   ")");
  }
  return {AssetState::up_to_date,
          "up to date (input " + (hashes.empty() ? "not present" : hashes) + ", same parameters)"};
}

std::filesystem::path find_baked_asset(const PlannedAsset& planned, const std::filesystem::path& folder) {
  if (!planned.file_name.empty()) return folder / planned.file_name;
  const std::string prefix = asset_name_prefix(planned.recipe);
  std::vector<std::filesystem::path> matches;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) == 0 && name.size() == prefix.size() + 16 + 4 &&
        check_asset_freshness(planned, it->path()).state == AssetState::up_to_date)
      matches.push_back(it->path());
  }
  if (matches.size() > 1) {
    std::sort(matches.begin(), matches.end());
    throw Error(ExitCode::invalid_input,
                std::to_string(matches.size()) + " baked " + planned.recipe.kind +
                    " assets match and the inputs to tell "
                    "them apart are missing: remove the old ones ('microbake bake --prune' where the inputs are)",
                matches[0].string() + ", " + matches[1].string());
  }
  return matches.empty() ? std::filesystem::path() : matches[0];
}

}  // namespace mbk
