// The `graph` kind (formats/kind_graph.cpp): the hand-built fixture and a baked analysis have no findings.
#include <gtest/gtest.h>

#include <random>

#include "formats/validate.h"
#include "libbake/synth/graph_asset.h"
#include "tests/formats/graph_fixtures.h"

namespace mbk {
namespace {

TEST(GraphKind, HandBuiltFixtureHasNoFindings) {
  const auto findings = validate_asset(test::graph_bytes());
  EXPECT_TRUE(findings.empty()) << findings.front().message;
}

TEST(GraphKind, BakedAnalysisIsValid) {
  ExemplarGraph g;
  g.exemplars = {{"a", "a.png", "a.png"}, {"b", "b.png", "b.png"}, {"c", "c.png", "c.png"}};
  g.edges = {{0, 1, 2}, {1, 2, 1}, {2, 2, 1}};
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<Image> images(3, Image{16, 16, 3, {}});
  for (Image& im : images)
    for (int i = 0; i < 16 * 16 * 3; ++i) im.pixels.push_back(u(rng));
  GraphAnalysisOptions options;
  const GraphAnalysis a = analyse_graph(g, images, options, Progress::silent());
  const auto findings =
      validate_asset(graph_asset_writer(g, a, options, nlohmann::json::object(), nlohmann::json::array()).serialize());
  EXPECT_TRUE(findings.empty()) << findings.front().message;
}

}  // namespace
}  // namespace mbk
