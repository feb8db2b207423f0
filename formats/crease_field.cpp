// The `crease` lattice: sizing, cell edge points, and reading the asset (see crease_field.h).
#include "formats/crease_field.h"

#include <algorithm>
#include <cmath>

#include "formats/asset.h"
#include "formats/asset_writer.h"
#include "formats/error.h"

namespace mbk {
namespace {

constexpr uint32_t kMaxSide = 16384;  // the normal maps' limit (libbake/image/normal_map.h)

struct SectionShape {
  const char* name;
  ElementType type;
  std::vector<uint64_t> shape;
};

std::vector<SectionShape> section_shapes(uint32_t w, uint32_t h) {
  return {{kCreaseNormalsSection, ElementType::f32, {h, w, 3}},
          {kCreaseDistanceSection, ElementType::f32, {h + 2, w + 2}},
          {kCreaseGradientSection, ElementType::f32, {h + 2, w + 2, 2}},
          {kCreaseSideSection, ElementType::i8, {h + 2, w + 2}},
          {kCreaseCrossingHSection, ElementType::f32, {h + 2, w + 1}},
          {kCreaseCrossingVSection, ElementType::f32, {h + 1, w + 2}},
          {kCreaseSegmentsSection, ElementType::u16, {h + 1, w + 1}}};
}

std::string shape_text(const std::vector<uint64_t>& shape) {
  std::string t = "[";
  for (size_t i = 0; i < shape.size(); ++i) t += (i ? ", " : "") + std::to_string(shape[i]);
  return t + "]";
}

// Empty when the asset's section has the expected type and shape, else what differs.
std::string shape_mismatch(const Asset& asset, const SectionShape& s) {
  const SectionInfo& info = asset.section(s.name);
  if (info.type == s.type && info.shape == s.shape) return {};
  return "'" + std::string(s.name) + "' is " + std::string(element_name(info.type)) + " " + shape_text(info.shape) +
         ", should be " + std::string(element_name(s.type)) + " " + shape_text(s.shape);
}

}  // namespace

int crease_pair_bit(int a, int b) {
  for (int bit = 0; bit < 6; ++bit)
    if ((kCreasePairFirst[bit] == a && kCreasePairSecond[bit] == b) ||
        (kCreasePairFirst[bit] == b && kCreasePairSecond[bit] == a))
      return bit;
  return -1;
}

void CreaseField::allocate(uint32_t w, uint32_t h) {
  allocate_lattice(w, h);
  const size_t samples = size_t(w + 2) * (h + 2);
  distance.assign(samples, 0.0f);
  gradient.assign(samples * 2, 0.0f);
  side.assign(samples, int8_t(1));
}

void CreaseField::allocate_lattice(uint32_t w, uint32_t h) {
  width = w;
  height = h;
  normals.assign(size_t(w) * h * 3, 0.0f);
  distance.clear();
  gradient.clear();
  side.clear();
  crossing_h.assign(size_t(h + 2) * (w + 1), kCreaseNoCrossing);
  crossing_v.assign(size_t(h + 1) * (w + 2), kCreaseNoCrossing);
  segments.assign(size_t(h + 1) * (w + 1), 0);
  junction_cells.clear();
  junction_points.clear();
  junction_spokes.clear();
}

int64_t CreaseField::junction_index(size_t cell) const {
  const auto it = std::lower_bound(junction_cells.begin(), junction_cells.end(), cell);
  return it != junction_cells.end() && *it == cell ? int64_t(it - junction_cells.begin()) : -1;
}

bool crease_point_inside_edge_points(const CreaseCellEdges& e, double u, double v, double margin) {
  for (int k = 0; k < 4; ++k) {
    const int n = (k + 1) % 4;
    const double ax = e.px[n] - e.px[k], ay = e.py[n] - e.py[k];
    // P0 -> P1 -> P2 -> P3 turns clockwise on screen (v down): inside is where the cross product is positive.
    const double cross = ax * (v - e.py[k]) - ay * (u - e.px[k]);
    if (!(cross >= margin * std::hypot(ax, ay)) || !(cross > 0.0)) return false;
  }
  return true;
}

CreaseCellEdges crease_cell_edges(const CreaseField& f, uint32_t i, uint32_t j) {
  CreaseCellEdges c;
  // t along +x or +y for edges e0..e3 (top, right, bottom, left).
  const float t[4] = {f.crossing_h[f.h_edge_index(i, j)], f.crossing_v[f.v_edge_index(i + 1, j)],
                      f.crossing_h[f.h_edge_index(i, j + 1)], f.crossing_v[f.v_edge_index(i, j)]};
  for (int k = 0; k < 4; ++k) {
    c.crossing[k] = t[k] != kCreaseNoCrossing;
    const double s = c.crossing[k] ? double(t[k]) : 0.5;
    // Edge k runs C_k -> C_{k+1}: e0 +x, e1 +y, e2 -x, e3 -y; t is measured along +x / +y.
    c.along[k] = k < 2 ? s : 1.0 - s;
    // Edge points in cell-local coordinates: e0 top (s, 0), e1 right (1, s), e2 bottom (s, 1), e3 left (0, s).
    c.px[k] = k == 1 ? 1.0 : k == 3 ? 0.0 : s;
    c.py[k] = k == 0 ? 0.0 : k == 2 ? 1.0 : s;
  }
  c.mask = f.segments[f.cell_index(i, j)];
  c.junction = false;
  c.spokes = 0;
  if (c.mask & kCreaseJunctionBit) {
    const int64_t n = f.junction_index(f.cell_index(i, j));
    if (n >= 0) {
      c.junction = true;
      c.ex = f.junction_points[2 * size_t(n)];
      c.ey = f.junction_points[2 * size_t(n) + 1];
      c.spokes = f.junction_spokes[size_t(n)];
    }
    return c;
  }
  // P0P2 runs top to bottom, P1P3 right to left; E is where they cross (never parallel: one runs from the top
  // edge to the bottom one, the other from the right edge to the left one).
  const double ax = c.px[2] - c.px[0], ay = 1.0, bx = c.px[3] - c.px[1], by = c.py[3] - c.py[1];
  const double cx = c.px[1] - c.px[0], cy = c.py[1] - c.py[0];
  const double s02 = (cx * by - cy * bx) / (ax * by - ay * bx);
  c.ex = c.px[0] + s02 * ax;
  c.ey = s02;
  if (c.mask & (1u << 4)) c.spokes |= 0x05;
  if (c.mask & (1u << 5)) c.spokes |= 0x0a;
  return c;
}

void add_crease_sections(AssetWriter& writer, CreaseField&& f) {
  for (const SectionShape& s : section_shapes(f.width, f.height)) {
    const std::string name = s.name;
    if (name == kCreaseNormalsSection) writer.add(name, s.shape, std::move(f.normals));
    if (name == kCreaseDistanceSection) writer.add(name, s.shape, std::move(f.distance));
    if (name == kCreaseGradientSection) writer.add(name, s.shape, std::move(f.gradient));
    if (name == kCreaseSideSection) writer.add(name, s.shape, std::move(f.side));
    if (name == kCreaseCrossingHSection) writer.add(name, s.shape, std::move(f.crossing_h));
    if (name == kCreaseCrossingVSection) writer.add(name, s.shape, std::move(f.crossing_v));
    if (name == kCreaseSegmentsSection) writer.add(name, s.shape, std::move(f.segments));
  }
  const uint64_t n = f.junction_cells.size();
  writer.add(kCreaseJunctionCellsSection, {n}, std::move(f.junction_cells));
  writer.add(kCreaseJunctionPointsSection, {n, 2}, std::move(f.junction_points));
  writer.add(kCreaseJunctionSpokesSection, {n}, std::move(f.junction_spokes));
}

std::string parse_crease_size(const Asset& asset, uint32_t& width, uint32_t& height) {
  const nlohmann::json& p = asset.metadata()["parameters"];
  if (!p.is_object()) return "parameters is not an object";
  uint32_t* fields[] = {&width, &height};
  const char* names[] = {"width", "height"};
  for (int i = 0; i < 2; ++i) {
    const auto it = p.find(names[i]);
    if (it == p.end() || !it->is_number_unsigned() || it->get<uint64_t>() < 1 || it->get<uint64_t>() > kMaxSide)
      return std::string("parameters.") + names[i] + " missing or not an integer in 1..16384";
    *fields[i] = it->get<uint32_t>();
  }
  return {};
}

std::string check_crease_section_shapes(const Asset& asset, uint32_t width, uint32_t height) {
  for (const SectionShape& s : section_shapes(width, height))
    if (std::string problem = shape_mismatch(asset, s); !problem.empty()) return problem;
  const SectionInfo* cells = asset.find(kCreaseJunctionCellsSection);
  const SectionInfo* points = asset.find(kCreaseJunctionPointsSection);
  const SectionInfo* spokes = asset.find(kCreaseJunctionSpokesSection);
  if (!cells && !points && !spokes) return {};
  if (!cells || !points || !spokes)
    return "the junction sections are not all present (junction_cells, junction_points, junction_spokes)";
  const uint64_t n = cells->shape.empty() ? 0 : cells->shape[0];
  for (const SectionShape& s : {SectionShape{kCreaseJunctionCellsSection, ElementType::u32, {n}},
                                SectionShape{kCreaseJunctionPointsSection, ElementType::f32, {n, 2}},
                                SectionShape{kCreaseJunctionSpokesSection, ElementType::u8, {n}}})
    if (std::string problem = shape_mismatch(asset, s); !problem.empty()) return problem;
  return {};
}

CreaseField read_crease_field(const Asset& asset) {
  CreaseField f;
  std::string problem = parse_crease_size(asset, f.width, f.height);
  if (problem.empty()) problem = check_crease_section_shapes(asset, f.width, f.height);
  if (!problem.empty()) throw Error(ExitCode::invalid_input, "crease asset: " + problem);
  f.normals = asset.read<float>(kCreaseNormalsSection);
  f.distance = asset.read<float>(kCreaseDistanceSection);
  f.gradient = asset.read<float>(kCreaseGradientSection);
  f.side = asset.read<int8_t>(kCreaseSideSection);
  f.crossing_h = asset.read<float>(kCreaseCrossingHSection);
  f.crossing_v = asset.read<float>(kCreaseCrossingVSection);
  f.segments = asset.read<uint16_t>(kCreaseSegmentsSection);
  if (asset.find(kCreaseJunctionCellsSection)) {
    f.junction_cells = asset.read<uint32_t>(kCreaseJunctionCellsSection);
    f.junction_points = asset.read<float>(kCreaseJunctionPointsSection);
    f.junction_spokes = asset.read<uint8_t>(kCreaseJunctionSpokesSection);
  }
  return f;
}

}  // namespace mbk
