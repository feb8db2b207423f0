// Baking the prefiltered colour-map table (see colormap_table.h).
#include "libbake/colormap/colormap_table.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"
#include "libbake/core/parallel.h"

namespace mbk {
namespace {

// C as the file stores it. Built element by element into new arrays: GCC 12.2 at -O3 vectorizes the in-place
// form `for (double& v : colour) v = double(float(v));` over the RGB triples and drops the rounding (reproduced
// with a 10-line program; test: ColormapTable.SingleKnotIsConstant, whose naive error must be exactly 0).
ColormapCurve rounded_to_float(const ColormapCurve& curve) {
  ColormapCurve out;
  for (double x : curve.knots) out.knots.push_back(double(float(x)));
  for (const auto& c : curve.colors)
    out.colors.push_back({double(float(c[0])), double(float(c[1])), double(float(c[2]))});
  return out;
}

// Per row j: max and sum of squares of the lookup error at the cell centres between rows j and j + 1, and the
// naive error of row j. Reduced serially in row order so that the figures do not depend on the thread count.
struct RowErrors {
  double lookup_max = 0.0, lookup_squares = 0.0, naive_max = 0.0;
};

}  // namespace

nlohmann::json ColormapTableStatistics::to_json() const {
  return {{"lookup_max_error", lookup_max_error},
          {"lookup_rms_error", lookup_rms_error},
          {"naive_max_error", naive_max_error}};
}

BakedColormap bake_colormap_table(const ColormapCurve& curve, const ColormapTableOptions& options, Progress& progress) {
  auto side_ok = [](uint32_t s) { return s >= kColormapMinSide && s <= kColormapMaxSide; };
  if (!side_ok(options.width) || !side_ok(options.height))
    throw Error(ExitCode::bad_command_line, "--size must be WxH with each side in " + std::to_string(kColormapMinSide) +
                                                ".." + std::to_string(kColormapMaxSide));
  if (!std::isfinite(options.mean_min) || !std::isfinite(options.mean_max) || !(options.mean_max > options.mean_min))
    throw Error(ExitCode::invalid_input, "the colour map's domain is empty");
  if (!std::isfinite(options.sigma_max) || options.sigma_max < 0.0)
    throw Error(ExitCode::bad_command_line, "--sigma-max must be a positive number");
  BakedColormap baked;
  baked.curve = rounded_to_float(curve);
  if (const std::string problem = colormap_curve_problem(baked.curve); !problem.empty())
    throw Error(ExitCode::invalid_input, "invalid colour map: " + problem);
  ColormapTable& t = baked.table;
  t.width = options.width;
  t.height = options.height;
  t.mean_min = float(options.mean_min);
  t.mean_max = float(options.mean_max);
  t.sigma_max = options.sigma_max > 0.0 ? options.sigma_max : 0.5 * (t.mean_max - t.mean_min);
  t.sigma_max = float(t.sigma_max);  // parameters are exact in the file's JSON; keep them float-representable
  t.values.assign(size_t(t.width) * t.height * 3, 0.0f);

  progress.start("colormap: convolving", 2 * uint64_t(t.height));
  parallel_for(0, t.height, [&](int64_t j) {
    for (uint32_t i = 0; i < t.width; ++i) {
      const auto v = baked.curve.convolved(t.mean_at(i), t.sigma_at(uint32_t(j)));
      for (int c = 0; c < 3; ++c) t.values[(size_t(j) * t.width + i) * 3 + c] = float(v[c]);
    }
    progress.advance();
  });

  std::vector<RowErrors> rows(t.height);
  parallel_for(0, t.height, [&](int64_t row) {
    const uint32_t j = uint32_t(row);
    RowErrors& e = rows[j];
    for (uint32_t i = 0; i < t.width; ++i) {
      const auto naive = baked.curve.at(t.mean_at(i));
      for (int c = 0; c < 3; ++c)
        e.naive_max = std::max(e.naive_max, std::abs(double(t.values[(size_t(j) * t.width + i) * 3 + c]) - naive[c]));
    }
    if (j + 1 < t.height)
      for (uint32_t i = 0; i + 1 < t.width; ++i) {
        const double m = 0.5 * (t.mean_at(i) + t.mean_at(i + 1)), s = 0.5 * (t.sigma_at(j) + t.sigma_at(j + 1));
        const auto exact = baked.curve.convolved(m, s), looked_up = t.lookup(m, s);
        for (int c = 0; c < 3; ++c) {
          const double d = std::abs(looked_up[c] - exact[c]);
          e.lookup_max = std::max(e.lookup_max, d);
          e.lookup_squares += d * d;
        }
      }
    progress.advance();
  });
  progress.finish();
  double squares = 0.0;
  for (const RowErrors& e : rows) {
    baked.statistics.lookup_max_error = std::max(baked.statistics.lookup_max_error, e.lookup_max);
    baked.statistics.naive_max_error = std::max(baked.statistics.naive_max_error, e.naive_max);
    squares += e.lookup_squares;
  }
  baked.statistics.lookup_rms_error = std::sqrt(squares / (3.0 * (t.width - 1) * (t.height - 1)));
  return baked;
}

AssetWriter colormap_asset_writer(const BakedColormap& baked, const nlohmann::json& input,
                                  const std::string& encoding) {
  const ColormapTable& t = baked.table;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input});
  metadata["parameters"] = {{"width", t.width},
                            {"height", t.height},
                            {"mean_min", t.mean_min},
                            {"mean_max", t.mean_max},
                            {"sigma_max", t.sigma_max}};
  metadata["conventions"] = {
      {"color_space", "linear RGB (input decoded from " + encoding + ")"},
      {"colormap", "piecewise linear between knots; two knots at one position make a jump (right-continuous)"},
      {"extension", "clamp: C(x) = first colour below the first knot, last colour above the last knot"},
      {"table",
       "entry (j, i) = [C * N(0, sigma_j^2)](m_i), m_i = mean_min + i (mean_max - mean_min) / (width - 1), "
       "sigma_j = j sigma_max / (height - 1); row 0 is C"},
      {"lookup", "bilinear in (mean, sigma), both clamped to the table's range"}};
  metadata["statistics"] = baked.statistics.to_json();
  metadata["statistics"]["knots"] = baked.curve.knots.size();
  std::vector<float> knots, colors;
  for (size_t k = 0; k < baked.curve.knots.size(); ++k) {
    knots.push_back(float(baked.curve.knots[k]));
    for (double c : baked.curve.colors[k]) colors.push_back(float(c));
  }
  AssetWriter writer("colormap", std::move(metadata));
  writer.add(std::string(kColormapKnotsSection), {knots.size()}, knots);
  writer.add(std::string(kColormapColorsSection), {knots.size(), 3}, colors);
  writer.add(std::string(kColormapTableSection), {t.height, t.width, 3}, t.values);
  return writer;
}

}  // namespace mbk
