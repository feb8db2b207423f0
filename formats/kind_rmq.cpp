// Asset kind 3, `rmq`: the 2-D sparse table of min/max normal components of an example normal map
// ([Wang20] Sec. 4.4, 5.1): section "table" (u16 or u8 [levels, height, width, 4], formats/rmq_layout.h) and
// section "range" (f64 [2, 2], formats/rmq_quantization.h). formats/SPEC.md, "Kind 3: rmq".
//
// Invariants `validate` checks, reading every entry once per check (a 2048 x 2048 table at the default
// patch, 7 levels and 224 MiB, takes well under a second): parameters (13001), section shapes (13002),
// range finite with lo <= hi (13003), min <= max in every entry (13004), and nesting (13005): every
// level-(k+1) entry contains its four level-k children (x or x + 2^k, row or row + 2^k), children outside
// the example skipped. Checks run on the codes: the dequantization is monotone, so ordered codes are
// ordered values.
#include <cstring>
#include <string>

#include "formats/number_text.h"
#include "formats/asset.h"
#include "formats/asset_kind.h"
#include "formats/rmq_layout.h"

namespace mbk {
namespace {

const char* const kComponent[4] = {"min_x", "max_x", "min_y", "max_y"};

std::string at_text(uint32_t level, uint32_t x, uint32_t row) {
  return "level " + number_text(level) + " texel (" + number_text(x) + ", " + number_text(row) + ")";
}

// Rows of one level copied into typed buffers (section bytes are not typed memory), so that the counting
// loops below are plain branch-free passes the compiler vectorizes.
template <typename Code>
class LevelRow {
 public:
  LevelRow(const RmqLayout& layout, const uint8_t* table)
      : L_(layout), table_(table), codes_(size_t(layout.width) * 4) {}
  const Code* read(uint32_t level, uint32_t row) {
    std::memcpy(codes_.data(), table_ + L_.entry_index(level, 0, row) * 4 * sizeof(Code), codes_.size() * sizeof(Code));
    return codes_.data();
  }

 private:
  const RmqLayout& L_;
  const uint8_t* table_;
  std::vector<Code> codes_;
};

// Entries among n with min_x > max_x or min_y > max_y.
template <typename Code>
uint64_t count_unordered(const Code* e, uint32_t n) {
  uint64_t bad = 0;
  for (uint32_t i = 0; i < n; ++i, e += 4) bad += (e[0] > e[1]) | (e[2] > e[3]);
  return bad;
}

// Parent entries among n that do not contain the child entry at the same index.
template <typename Code>
uint64_t count_not_containing(const Code* p, const Code* c, uint32_t n) {
  uint64_t bad = 0;
  for (uint32_t i = 0; i < n; ++i, p += 4, c += 4) bad += (p[0] > c[0]) | (p[1] < c[1]) | (p[2] > c[2]) | (p[3] < c[3]);
  return bad;
}

// The first violations, described for the message (only run when the counts found some).
template <typename Code>
Finding describe_unordered(const RmqLayout& L, LevelRow<Code>& rows, uint64_t count) {
  for (uint32_t k = 0; k < L.levels; ++k)
    for (uint32_t row = 0; row < L.height; ++row) {
      const Code* e = rows.read(k, row);
      for (uint32_t x = 0; x < L.width; ++x, e += 4)
        for (int c = 0; c < 4; c += 2)
          if (e[c] > e[c + 1])
            return make_finding(
                msg::rmq_min_above_max,
                at_text(k, x, row) + ": " + kComponent[c] + " code " + number_text(e[c]) + " > " + kComponent[c + 1] +
                    " code " + number_text(e[c + 1]) + " (" + number_text(count) + " entries)",
                {{"level", k}, {"x", x}, {"row", row}, {"component", c == 0 ? "x" : "y"}, {"entries", count}});
    }
  return {};
}

// Visits every parent-child pairing of the nesting check once: for each level k >= 1 and row, the level-(k-1)
// rows `row` and `row + 2^(k-1)` inside the example, each at column offsets dx = 0 and 2^(k-1) (when inside).
// `visit(k, row, dx, dy, parent, child, n)` sees the n parents of the row from x = 0 and, at the same index, their
// children at x + dx; it returns false to stop.
template <typename Code, typename Visit>
void for_each_nesting_pair(const RmqLayout& L, LevelRow<Code>& parents, LevelRow<Code>& children, Visit visit) {
  for (uint32_t k = 1; k < L.levels; ++k) {
    const uint32_t half = 1u << (k - 1);
    for (uint32_t row = 0; row < L.height; ++row) {
      const Code* p = parents.read(k, row);
      for (uint32_t dy = 0; dy <= half && row + dy < L.height; dy += half) {
        const Code* ch = children.read(k - 1, row + dy);
        for (uint32_t dx = 0; dx <= half && dx < L.width; dx += half)
          if (!visit(k, row, dx, dy, p, ch + 4 * dx, L.width - dx)) return;
      }
    }
  }
}

template <typename Code>
Finding describe_not_nested(const RmqLayout& L, LevelRow<Code>& parents, LevelRow<Code>& children, uint64_t count) {
  Finding first;
  for_each_nesting_pair(
      L, parents, children,
      [&](uint32_t k, uint32_t row, uint32_t dx, uint32_t dy, const Code* p, const Code* ch, uint32_t n) {
        for (uint32_t x = 0; x < n; ++x)
          for (int c = 0; c < 4; ++c) {
            const Code parent = p[4 * x + c], child = ch[4 * x + c];
            if (c % 2 == 0 ? parent <= child : parent >= child) continue;
            first = make_finding(msg::rmq_not_nested,
                                 at_text(k, x, row) + ": " + kComponent[c] + " code " + number_text(parent) +
                                     " does not contain child " + at_text(k - 1, x + dx, row + dy) + "'s " +
                                     number_text(child) + " (" + number_text(count) + " parent-child pairs)",
                                 {{"level", k},
                                  {"x", x},
                                  {"row", row},
                                  {"child_x", x + dx},
                                  {"child_row", row + dy},
                                  {"component", kComponent[c]},
                                  {"pairs", count}});
            return false;
          }
        return true;
      });
  return first;
}

template <typename Code>
void check_codes(const RmqLayout& L, const uint8_t* table, std::vector<Finding>& out) {
  LevelRow<Code> parents(L, table), children(L, table);
  uint64_t unordered = 0, not_nested = 0;
  for (uint32_t k = 0; k < L.levels; ++k)
    for (uint32_t row = 0; row < L.height; ++row) unordered += count_unordered(parents.read(k, row), L.width);
  for_each_nesting_pair(L, parents, children,
                        [&](uint32_t, uint32_t, uint32_t, uint32_t, const Code* p, const Code* ch, uint32_t n) {
                          not_nested += count_not_containing(p, ch, n);
                          return true;
                        });
  if (unordered) out.push_back(describe_unordered(L, parents, unordered));
  if (not_nested) out.push_back(describe_not_nested(L, parents, children, not_nested));
}

void check_rmq(const Asset& a, std::vector<Finding>& out) {
  RmqLayout layout;
  if (std::string problem = parse_rmq_layout(a.metadata()["parameters"], layout); !problem.empty()) {
    out.push_back(make_finding(msg::rmq_bad_parameters, problem));
    return;
  }
  if (std::string problem = check_rmq_section_shapes(a, layout); !problem.empty()) {
    out.push_back(make_finding(msg::rmq_section_shape, problem));
    return;
  }
  std::array<RmqRange, 2> range;
  if (std::string problem = read_rmq_range(a, range); !problem.empty())
    out.push_back(make_finding(msg::rmq_bad_range, problem));
  // The codes are checked whatever the range: their order does not depend on it.
  const auto bytes = a.bytes_of(a.section("table"));
  if (layout.bits == 8)
    check_codes<uint8_t>(layout, bytes.data(), out);
  else
    check_codes<uint16_t>(layout, bytes.data(), out);
}

}  // namespace

AssetKind rmq_kind() {
  AssetKind k;
  k.id = 3;
  k.name = "rmq";
  k.summary = "2-D sparse table of min/max normal components over power-of-two squares (glint range queries)";
  k.required_sections = {{"table", {ElementType::u16, ElementType::u8}, 4}, {"range", {ElementType::f64}, 2}};
  k.knows_section = [](const std::string& name) { return name == "table" || name == "range"; };
  k.check_invariants = check_rmq;
  return k;
}

}  // namespace mbk
