// Asset kind 6, `crease`: [Parilov05]'s discontinuity signature, distance, gradient and side maps with the
// normal map (formats/crease_field.h). formats/SPEC.md, "Kind 6: crease".
//
// Invariants `validate` checks, in this order (the first finding ends the check): parameters (16001), section
// types and shapes (16002), finite floats (16003), crossings -1 or in [kCreaseMinT, 1 - kCreaseMinT] (16004),
// allowed cell configurations (16005: at most two segment bits, each between two crossed edges, no unknown
// bits, direction bits only with their segment; or the junction bit alone), junction records (16010: cells
// increasing, one per junction word, two to four spokes on crossed edges, directions only on spokes, the point
// strictly inside the quadrilateral of the cell's edge points), distances >= 0 (16006), unit gradients (16007:
// |len - 1| <= 1e-5, float rounding of a renormalised vector is ~1e-7), sides +1/-1 (16008), unit normals with
// z >= 0 (16009, same tolerance).
#include <bit>
#include <cmath>
#include <string>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/crease_field.h"

namespace mbk {
namespace {

constexpr double kUnitTolerance = 1e-5;

// Every float finite, and every edge crossing either none or strictly inside its edge.
bool check_crease_values(const CreaseField& f, std::vector<Finding>& out) {
  const std::pair<const char*, const std::vector<float>*> floats[] = {
      {kCreaseNormalsSection, &f.normals},      {kCreaseDistanceSection, &f.distance},
      {kCreaseGradientSection, &f.gradient},    {kCreaseCrossingHSection, &f.crossing_h},
      {kCreaseCrossingVSection, &f.crossing_v}, {kCreaseJunctionPointsSection, &f.junction_points}};
  for (const auto& [name, values] : floats)
    for (size_t i = 0; i < values->size(); ++i)
      if (!std::isfinite((*values)[i])) {
        out.push_back(make_finding(msg::crease_non_finite, "'" + std::string(name) + "' element " + number_text(i),
                                   {{"section", name}, {"index", i}}));
        return false;
      }
  for (const auto& [name, values] :
       {std::pair{kCreaseCrossingHSection, &f.crossing_h}, std::pair{kCreaseCrossingVSection, &f.crossing_v}})
    for (size_t i = 0; i < values->size(); ++i) {
      const float t = (*values)[i];
      if (t != kCreaseNoCrossing && !(t >= kCreaseMinT && t <= 1.0f - kCreaseMinT)) {
        out.push_back(make_finding(msg::crease_bad_crossing,
                                   "'" + std::string(name) + "' edge " + number_text(i) + " is " + number_text(t),
                                   {{"section", name}, {"index", i}}));
        return false;
      }
    }
  return true;
}

// Every cell's segment bits: known bits, at most kCreaseMaxSegmentsPerCell segments, direction bits only on
// segments, and each segment's two edges crossed.
bool check_crease_cells(const CreaseField& f, std::vector<Finding>& out) {
  for (uint32_t j = 0; j < f.cells_y(); ++j)
    for (uint32_t i = 0; i < f.cells_x(); ++i) {
      const CreaseCellEdges c = crease_cell_edges(f, i, j);
      std::string problem;
      const uint16_t segments = c.mask & kCreaseSegmentBits;
      if (c.mask & kCreaseJunctionBit)
        problem = c.mask != kCreaseJunctionBit ? "a junction word with other bits" : "";
      else if (c.mask & ~(kCreaseSegmentBits | kCreaseReversedBits))
        problem = "unknown bits";
      else if (std::popcount(segments) > int(kCreaseMaxSegmentsPerCell))
        problem = number_text(std::popcount(segments)) + " segments";
      else if ((c.mask >> 8) & ~segments)
        problem = "a direction bit without its segment";
      for (int bit = 0; bit < 6 && problem.empty(); ++bit)
        if ((segments >> bit) & 1u)
          for (int e : {kCreasePairFirst[bit], kCreasePairSecond[bit]})
            if (!c.crossing[e])
              problem =
                  "segment bit " + number_text(bit) + " ends on edge " + number_text(e) + ", which has no crossing";
      if (!problem.empty()) {
        out.push_back(make_finding(msg::crease_bad_segments,
                                   "cell (" + number_text(i) + ", " + number_text(j) + "): " + problem,
                                   {{"section", kCreaseSegmentsSection}, {"cell", {i, j}}}));
        return false;
      }
    }
  return true;
}

// Every junction record: cells increasing and in range, each the record of a junction word and every junction word
// with one, two to four spokes on crossed edges, direction bits only on spokes, E strictly inside the edge points.
bool check_crease_junctions(const CreaseField& f, std::vector<Finding>& out) {
  const auto finding = [&](size_t n, const std::string& problem) {
    out.push_back(make_finding(msg::crease_bad_junction, "junction record " + number_text(n) + ": " + problem,
                               {{"section", kCreaseJunctionCellsSection}, {"index", n}}));
    return false;
  };
  size_t words = 0;
  for (uint16_t w : f.segments) words += (w & kCreaseJunctionBit) != 0;
  if (words != f.junction_cells.size())
    return finding(0, number_text(words) + " junction words but " + number_text(f.junction_cells.size()) + " records");
  for (size_t n = 0; n < f.junction_cells.size(); ++n) {
    const size_t cell = f.junction_cells[n];
    if (cell >= f.segments.size()) return finding(n, "cell " + number_text(cell) + " out of range");
    if (n > 0 && cell <= f.junction_cells[n - 1]) return finding(n, "cells not increasing");
    if (!(f.segments[cell] & kCreaseJunctionBit)) return finding(n, "its cell's word is not a junction");
    const CreaseCellEdges e = crease_cell_edges(f, uint32_t(cell % f.cells_x()), uint32_t(cell / f.cells_x()));
    const uint8_t spokes = f.junction_spokes[n] & 0x0f, directions = f.junction_spokes[n] >> 4;
    if (std::popcount(unsigned(spokes)) < 2) return finding(n, "fewer than two spokes");
    if (directions & ~spokes) return finding(n, "a direction bit without its spoke");
    for (int k = 0; k < 4; ++k)
      if ((spokes >> k) & 1u && !e.crossing[k])
        return finding(n, "spoke " + number_text(k) + " ends on an edge without a crossing");
    if (!crease_point_inside_edge_points(e, e.ex, e.ey, 0.0))
      return finding(n,
                     "the point (" + number_text(e.ex) + ", " + number_text(e.ey) + ") is not inside the edge points");
  }
  return true;
}

// Every sample's distance non-negative, gradient of unit length and side +1 or -1.
bool check_crease_samples(const CreaseField& f, std::vector<Finding>& out) {
  for (size_t k = 0; k < f.distance.size(); ++k) {
    const uint32_t i = uint32_t(k % f.samples_x()), j = uint32_t(k / f.samples_x());
    const nlohmann::json at = {{"sample", {i, j}}};
    const std::string where = "sample (" + number_text(i) + ", " + number_text(j) + ")";
    if (f.distance[k] < 0.0f) {
      out.push_back(make_finding(msg::crease_negative_distance, where + ": " + number_text(f.distance[k]), at));
      return false;
    }
    const double len = std::hypot(double(f.gradient[2 * k]), double(f.gradient[2 * k + 1]));
    if (std::abs(len - 1.0) > kUnitTolerance) {
      out.push_back(make_finding(msg::crease_gradient_not_unit, where + ": length " + number_text(len), at));
      return false;
    }
    if (f.side[k] != 1 && f.side[k] != -1) {
      out.push_back(make_finding(msg::crease_bad_side, where + ": " + number_text(int(f.side[k])), at));
      return false;
    }
  }
  return true;
}

void check_crease(const Asset& a, std::vector<Finding>& out) {
  uint32_t w = 0, h = 0;
  if (std::string problem = parse_crease_size(a, w, h); !problem.empty()) {
    out.push_back(make_finding(msg::crease_bad_parameters, problem, {{"key", "parameters"}}));
    return;
  }
  if (std::string problem = check_crease_section_shapes(a, w, h); !problem.empty()) {
    out.push_back(make_finding(msg::crease_section_shape, problem));
    return;
  }
  const CreaseField f = read_crease_field(a);
  if (!check_crease_values(f, out) || !check_crease_cells(f, out) || !check_crease_junctions(f, out) ||
      !check_crease_samples(f, out))
    return;
  for (size_t k = 0; k < f.normals.size() / 3; ++k) {
    const double x = f.normals[3 * k], y = f.normals[3 * k + 1], z = f.normals[3 * k + 2];
    const double len = std::sqrt(x * x + y * y + z * z);
    if (std::abs(len - 1.0) > kUnitTolerance || z < 0.0) {
      out.push_back(make_finding(msg::crease_bad_normal,
                                 "texel (" + number_text(k % w) + ", " + number_text(k / w) + "): length " +
                                     number_text(len) + ", z " + number_text(z),
                                 {{"texel", {k % w, k / w}}}));
      return;
    }
  }
}

}  // namespace

AssetKind crease_kind() {
  AssetKind k;
  k.id = kCreaseKindId;
  k.name = "crease";
  k.summary = "normal map with discontinuities: discontinuity signatures, distance, gradient and side maps";
  k.required_sections = {
      {kCreaseNormalsSection, {ElementType::f32}, 3},   {kCreaseDistanceSection, {ElementType::f32}, 2},
      {kCreaseGradientSection, {ElementType::f32}, 3},  {kCreaseSideSection, {ElementType::i8}, 2},
      {kCreaseCrossingHSection, {ElementType::f32}, 2}, {kCreaseCrossingVSection, {ElementType::f32}, 2},
      {kCreaseSegmentsSection, {ElementType::u16}, 2}};
  k.knows_section = [](const std::string& name) {
    for (const char* s : {kCreaseNormalsSection, kCreaseDistanceSection, kCreaseGradientSection, kCreaseSideSection,
                          kCreaseCrossingHSection, kCreaseCrossingVSection, kCreaseSegmentsSection,
                          kCreaseJunctionCellsSection, kCreaseJunctionPointsSection, kCreaseJunctionSpokesSection})
      if (name == s) return true;
    return false;
  };
  k.check_invariants = check_crease;
  return k;
}

}  // namespace mbk
