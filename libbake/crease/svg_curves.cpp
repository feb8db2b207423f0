// Reading discontinuity curves from the SVG subset described in curve_set.h: a small XML tag scanner (no
// entity or namespace processing: neither occurs in the attributes we read) and the path-data grammar of
// SVG 1.1 Sec. 8.3 for the line commands M L H V Z (absolute and relative). Anything that would draw
// something we cannot represent is an error naming the element and its line, never silently dropped.
#include <algorithm>
#include <charconv>
#include <cstring>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "formats/error.h"
#include "libbake/crease/curve_set.h"

namespace mbk {
namespace {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  size_t line = 0;
  bool self_closing = false;
};

// Elements whose content never draws: skipped with everything inside them.
const std::set<std::string> kSkippedContainers = {
    "title",  "desc",    "metadata",       "defs",           "style",  "clipPath", "mask", "marker",
    "symbol", "pattern", "linearGradient", "radialGradient", "filter", "script",   "font", "foreignObject"};
// Containers whose children draw.
const std::set<std::string> kGroups = {"g", "a"};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Scans the numbers of an attribute (SVG number grammar: sign, digits, fraction, exponent; separated by
// white space and/or one comma; "1.5.5" is 1.5 then .5).
class NumberScanner {
 public:
  NumberScanner(const std::string& text, std::string where) : s_(text), where_(std::move(where)) {}

  void skip_separators() {
    while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
    if (pos_ < s_.size() && s_[pos_] == ',') ++pos_;
    while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
  }
  bool at_end() {
    skip_separators();
    return pos_ >= s_.size();
  }
  bool at_number() {
    skip_separators();
    if (pos_ >= s_.size()) return false;
    const char c = s_[pos_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
  }
  char peek() {
    skip_separators();
    return pos_ < s_.size() ? s_[pos_] : '\0';
  }
  char take() { return s_[pos_++]; }

  double number() {
    skip_separators();
    const size_t start = pos_;
    size_t p = pos_;
    if (p < s_.size() && (s_[p] == '+' || s_[p] == '-')) ++p;
    const size_t digits_start = p;
    while (p < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p]))) ++p;
    bool any_digit = p > digits_start;
    if (p < s_.size() && s_[p] == '.') {
      ++p;
      const size_t frac_start = p;
      while (p < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p]))) ++p;
      any_digit = any_digit || p > frac_start;
    }
    if (!any_digit) {
      size_t end = start;
      while (end < s_.size() && !is_space(s_[end]) && s_[end] != ',') ++end;
      throw Error(
          ExitCode::invalid_input,
          "expected a number, found '" + (end > start ? s_.substr(start, end - start) : std::string("end")) + "'",
          where_);
    }
    if (p < s_.size() && (s_[p] == 'e' || s_[p] == 'E')) {
      size_t q = p + 1;
      if (q < s_.size() && (s_[q] == '+' || s_[q] == '-')) ++q;
      const size_t exp_start = q;
      while (q < s_.size() && std::isdigit(static_cast<unsigned char>(s_[q]))) ++q;
      if (q > exp_start) p = q;  // else the 'e' is not part of the number
    }
    double value = 0.0;
    const char* first = s_.data() + start + (s_[start] == '+' ? 1 : 0);
    const auto [ptr, ec] = std::from_chars(first, s_.data() + p, value);
    if (ec == std::errc::result_out_of_range || !std::isfinite(value))
      throw Error(ExitCode::invalid_input, "non-finite number '" + s_.substr(start, p - start) + "'", where_);
    if (ec != std::errc() || ptr != s_.data() + p)
      throw Error(ExitCode::invalid_input, "malformed number '" + s_.substr(start, p - start) + "'", where_);
    pos_ = p;
    return value;
  }

 private:
  const std::string& s_;
  std::string where_;
  size_t pos_ = 0;
};

class SvgReader {
 public:
  SvgReader(const std::string& text, std::string file, uint32_t width, uint32_t height)
      : text_(text), file_(std::move(file)), width_(width), height_(height) {}

  CurveSet read() {
    std::vector<std::string> stack;
    size_t skip_depth = 0;  // > 0 inside a skipped container
    bool seen_root = false;
    while (true) {
      const size_t open = text_.find('<', pos_);
      if (open == std::string::npos) break;
      pos_ = open;
      if (starts_with("<!--")) {
        skip_past("-->");
        continue;
      }
      if (starts_with("<![CDATA[")) {
        skip_past("]]>");
        continue;
      }
      if (starts_with("<?")) {
        skip_past("?>");
        continue;
      }
      if (starts_with("<!")) {
        skip_past(">");
        continue;
      }
      if (starts_with("</")) {
        const size_t close = text_.find('>', pos_);
        if (close == std::string::npos) fail_syntax("unterminated closing tag");
        pos_ = close + 1;
        if (stack.empty()) fail_syntax("closing tag without an opening tag");
        if (skip_depth > 0) --skip_depth;
        stack.pop_back();
        continue;
      }
      Element e = read_element();
      const bool skipped = skip_depth > 0 || kSkippedContainers.count(e.name) ||
                           e.name.find(':') != std::string::npos;  // editor namespaces (sodipodi:, inkscape:)
      if (!skipped) {
        if (!seen_root) {
          if (e.name != "svg") fail(e, "the root element must be <svg>, not <" + e.name + ">");
          seen_root = true;
          read_root(e);
        } else {
          visit(e);
        }
      }
      if (!e.self_closing) {
        if (stack.size() >= kMaxSvgNesting)
          fail(e, "elements nested more than " + std::to_string(kMaxSvgNesting) + " deep");
        stack.push_back(e.name);
        if (skipped) ++skip_depth;
      }
    }
    if (!seen_root) throw Error(ExitCode::invalid_input, "no <svg> element", file_);
    if (set_.curves.empty()) throw Error(ExitCode::invalid_input, "no curves in the file", file_);
    check_curves(set_, width_, height_);
    return std::move(set_);
  }

 private:
  bool starts_with(const char* prefix) const { return text_.compare(pos_, std::strlen(prefix), prefix) == 0; }

  // Lines are counted from the last offset asked about (the reader only moves forward), so that numbering every
  // element stays linear in the file's size.
  size_t line_at(size_t offset) const {
    offset = std::min(offset, text_.size());
    if (offset < line_offset_) line_offset_ = 0, line_ = 1;
    line_ += size_t(std::count(text_.begin() + ptrdiff_t(line_offset_), text_.begin() + ptrdiff_t(offset), '\n'));
    line_offset_ = offset;
    return line_;
  }

  [[noreturn]] void fail_syntax(const std::string& what) const {
    throw Error(ExitCode::invalid_input, "malformed SVG: " + what, file_ + ": line " + std::to_string(line_at(pos_)));
  }

  std::string where(const Element& e) const {
    std::string w = file_ + ": <" + e.name;
    if (e.attributes.count("id")) w += " id=\"" + e.attributes.at("id") + "\"";
    return w + "> line " + std::to_string(e.line);
  }

  [[noreturn]] void fail(const Element& e, const std::string& what) const {
    throw Error(ExitCode::invalid_input, what, where(e));
  }

  void skip_past(const char* end) {
    const size_t at = text_.find(end, pos_);
    if (at == std::string::npos) fail_syntax(std::string("missing '") + end + "'");
    pos_ = at + std::strlen(end);
  }

  Element read_element() {
    Element e;
    e.line = line_at(pos_);
    ++pos_;  // '<'
    auto name_char = [](char c) { return !is_space(c) && c != '>' && c != '/' && c != '='; };
    while (pos_ < text_.size() && name_char(text_[pos_])) e.name += text_[pos_++];
    if (e.name.empty()) fail_syntax("empty tag name");
    while (true) {
      while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
      if (pos_ >= text_.size()) fail_syntax("unterminated tag <" + e.name + ">");
      if (text_[pos_] == '>') {
        ++pos_;
        return e;
      }
      if (starts_with("/>")) {
        pos_ += 2;
        e.self_closing = true;
        return e;
      }
      std::string key;
      while (pos_ < text_.size() && name_char(text_[pos_])) key += text_[pos_++];
      while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
      if (key.empty() || pos_ >= text_.size() || text_[pos_] != '=')
        fail_syntax("expected name=\"value\" in <" + e.name + ">");
      ++pos_;
      while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
      if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\''))
        fail_syntax("attribute value must be quoted in <" + e.name + ">");
      const char quote = text_[pos_++];
      const size_t end = text_.find(quote, pos_);
      if (end == std::string::npos) fail_syntax("unterminated attribute value in <" + e.name + ">");
      e.attributes[key] = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
    }
  }

  std::vector<double> numbers(const Element& e, const std::string& attribute) {
    NumberScanner s(e.attributes.at(attribute), where(e) + " " + attribute);
    std::vector<double> out;
    while (!s.at_end()) out.push_back(s.number());
    return out;
  }

  // A length in user units: a number, optionally followed by "px".
  double length(const Element& e, const std::string& attribute) {
    std::string v = e.attributes.at(attribute);
    while (!v.empty() && is_space(v.back())) v.pop_back();
    if (v.size() > 2 && v.compare(v.size() - 2, 2, "px") == 0) v.resize(v.size() - 2);
    Element copy = e;
    copy.attributes[attribute] = v;
    const std::vector<double> n = numbers(copy, attribute);
    if (n.size() != 1 || !(n[0] > 0.0))
      fail(e, attribute + " must be a positive length in user units or px, not '" + e.attributes.at(attribute) + "'");
    return n[0];
  }

  void read_root(const Element& e) {
    if (e.attributes.count("transform")) fail(e, "unsupported SVG: transform attribute");
    if (e.attributes.count("viewBox")) {
      const std::vector<double> vb = numbers(e, "viewBox");
      if (vb.size() != 4 || !(vb[2] > 0.0) || !(vb[3] > 0.0))
        fail(e, "viewBox must be four numbers 'min-x min-y width height' with positive width and height");
      origin_ = Vec2(vb[0], vb[1]);
      scale_ = Vec2(width_ / vb[2], height_ / vb[3]);
    } else if (e.attributes.count("width") && e.attributes.count("height")) {
      scale_ = Vec2(width_ / length(e, "width"), height_ / length(e, "height"));
    }
  }

  Vec2 to_texels(double x, double y) const {
    return Vec2((x - origin_.x()) * scale_.x(), (y - origin_.y()) * scale_.y());
  }

  void add(CurvePolyline&& line) {
    if (line.points.size() >= 2) set_.curves.push_back(std::move(line));
  }

  void visit(const Element& e) {
    if (e.attributes.count("transform")) fail(e, "unsupported SVG: transform attribute");
    if (kGroups.count(e.name)) return;
    auto require = [&](std::initializer_list<const char*> names) {
      for (const char* n : names)
        if (!e.attributes.count(n)) fail(e, std::string("missing attribute ") + n);
    };
    if (e.name == "path") {
      require({"d"});
      read_path(e);
    } else if (e.name == "polyline" || e.name == "polygon") {
      require({"points"});
      const std::vector<double> n = numbers(e, "points");
      if (n.size() % 2) fail(e, "points holds an odd count of numbers (" + std::to_string(n.size()) + ")");
      CurvePolyline line{{}, e.name == "polygon", where(e)};
      for (size_t i = 0; i < n.size(); i += 2) line.points.push_back(to_texels(n[i], n[i + 1]));
      add(std::move(line));
    } else if (e.name == "line") {
      require({"x1", "y1", "x2", "y2"});
      double c[4];
      const char* names[4] = {"x1", "y1", "x2", "y2"};
      for (int i = 0; i < 4; ++i) {
        const std::vector<double> n = numbers(e, names[i]);
        if (n.size() != 1) fail(e, std::string(names[i]) + " must be one number");
        c[i] = n[0];
      }
      add(CurvePolyline{{to_texels(c[0], c[1]), to_texels(c[2], c[3])}, false, where(e)});
    } else if (e.name == "svg") {
      fail(e, "unsupported SVG: nested <svg>");
    } else {
      fail(e, "unsupported SVG element <" + e.name + "> (supported: path with M L H V Z, polyline, polygon, line, g)");
    }
  }

  // SVG 1.1 path data, line commands only. Coordinates are read in user units and mapped to texels.
  void read_path(const Element& e) {
    NumberScanner s(e.attributes.at("d"), where(e) + " d");
    Vec2 cur(0.0, 0.0), start(0.0, 0.0);  // user units
    CurvePolyline line{{}, false, where(e)};
    char command = '\0';
    auto finish = [&](bool closed) {
      line.closed = closed;
      add(std::move(line));
      line = CurvePolyline{{}, false, where(e)};
    };
    auto line_to = [&](const Vec2& p) {
      if (line.points.empty()) line.points.push_back(to_texels(start.x(), start.y()));  // after Z: from the start
      cur = p;
      line.points.push_back(to_texels(p.x(), p.y()));
    };
    while (!s.at_end()) {
      if (!s.at_number()) {
        command = s.take();
        if (command == 'Z' || command == 'z') {
          if (!line.points.empty()) finish(true);
          cur = start;
          continue;
        }
        if (std::string("MmLlHhVv").find(command) == std::string::npos)
          fail(e, std::string("unsupported SVG path command '") + command + "' (supported: M L H V Z, m l h v z)");
      } else if (command == '\0') {
        fail(e, "path data must start with a moveto (M or m)");
      }
      const bool relative = std::islower(static_cast<unsigned char>(command));
      switch (command) {
        case 'M':
        case 'm': {
          const double x = s.number(), y = s.number();
          finish(false);
          cur = relative ? Vec2(cur + Vec2(x, y)) : Vec2(x, y);
          start = cur;
          line.points.push_back(to_texels(cur.x(), cur.y()));
          command = relative ? 'l' : 'L';  // further pairs are line-tos
          break;
        }
        case 'L':
        case 'l': {
          const double x = s.number(), y = s.number();
          line_to(relative ? Vec2(cur + Vec2(x, y)) : Vec2(x, y));
          break;
        }
        case 'H':
        case 'h': {
          const double x = s.number();
          line_to(Vec2(relative ? cur.x() + x : x, cur.y()));
          break;
        }
        case 'V':
        case 'v': {
          const double y = s.number();
          line_to(Vec2(cur.x(), relative ? cur.y() + y : y));
          break;
        }
        default:
          fail(e, std::string("numbers after '") + command + "'");
      }
    }
    finish(false);
  }

  const std::string& text_;
  std::string file_;
  uint32_t width_, height_;
  size_t pos_ = 0;
  mutable size_t line_offset_ = 0, line_ = 1;  // line_at's cache: the line number at line_offset_
  Vec2 origin_ = Vec2::Zero(), scale_ = Vec2::Ones();
  CurveSet set_;
};

}  // namespace

CurveSet parse_svg_curves(const std::string& text, const std::string& file, uint32_t width, uint32_t height) {
  return SvgReader(text, file, width, height).read();
}

}  // namespace mbk
