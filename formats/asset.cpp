// The .mbk reader: structural parsing with findings, checksum verification, and the Asset accessor
// (formats/SPEC.md). Every offset, size and product is checked for overflow and bounds before use.
#include "formats/asset.h"

#include <Imath/half.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <utility>

#include "formats/atomic_file.h"
#include "formats/byte_io.h"
#include "formats/validate.h"

namespace mbk {
namespace {

std::string version_string(unsigned major, unsigned minor) {
  return std::to_string(major) + "." + std::to_string(minor);
}

// [begin, end) regions must not overlap; the checks below compute ends without overflow.
struct Region {
  uint64_t begin, end;
  std::string what;
};

// Two regions overlap when they share a byte; an empty region (a zero-length section) is a point, which may be
// another region's first byte or its end but not strictly inside it.
bool overlap(const Region& a, const Region& b) {
  if (a.begin == a.end) return b.begin < a.begin && a.begin < b.end;
  if (b.begin == b.end) return a.begin < b.begin && b.begin < a.end;
  return a.begin < b.end && b.begin < a.end;
}

// Strict JSON (nlohmann's parser is RFC 8259 but for duplicate keys, where the last would win): parses `text`
// and names in `repeated_key` the first key that an object holds twice, at any depth.
nlohmann::json parse_metadata_json(std::string_view text, std::string& repeated_key) {
  std::vector<std::set<std::string>> open_objects;
  const nlohmann::json::parser_callback_t watch = [&](int, nlohmann::json::parse_event_t event,
                                                      nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) open_objects.emplace_back();
    if (event == Event::object_end) open_objects.pop_back();
    if (event == Event::key && !open_objects.back().insert(parsed.get<std::string>()).second && repeated_key.empty())
      repeated_key = parsed.get<std::string>();
    return true;
  };
  return nlohmann::json::parse(text, watch, /*allow_exceptions=*/false);
}

bool in_bounds(uint64_t offset, uint64_t size, uint64_t total, uint64_t* end) {
  if (__builtin_add_overflow(offset, size, end)) return false;
  return *end <= total;
}

// Reads the container's structure in the order of SPEC section 9, recording findings; each step returns false
// (after recording why) when the file cannot be read further.
class ContainerParser {
 public:
  ContainerParser(std::span<const uint8_t> bytes, std::vector<Finding>& findings)
      : bytes_(bytes), b_(bytes.data()), n_(bytes.size()), findings_(findings) {}

  std::optional<ParsedContainer> parse() {
    if (!check_magic() || !read_header() || !check_header_regions() || !check_header_checksum() || !parse_metadata() ||
        !read_section_table() || !check_gaps())
      return std::nullopt;
    return std::move(p_);
  }

 private:
  bool fail(const MessageInfo& m, const std::string& specifics, nlohmann::json details = nlohmann::json::object()) {
    findings_.push_back(make_finding(m, specifics, std::move(details)));
    return false;
  }

  // Magic first, so that a short non-.mbk file is reported as "not an .mbk file".
  bool check_magic() {
    const size_t magic_n = std::min<size_t>(n_, kMagic.size());
    if (std::equal(bytes_.begin(), bytes_.begin() + magic_n, kMagic.begin()))
      return n_ >= kHeaderSize || fail(msg::file_too_small, std::to_string(n_) + " bytes, the header alone needs 64");
    // CR LF -> LF turns "\r\n\x1a\n" into "\n\x1a\n"; LF -> CR LF turns it into "\r\r\n\x1a\r\n".
    static const uint8_t kCrLfToLf[] = {0x89, 'M', 'B', 'K', '\n', 0x1A, '\n'};
    static const uint8_t kLfToCrLf[] = {0x89, 'M', 'B', 'K', '\r', '\r', '\n', 0x1A, '\r', '\n'};
    auto starts_with = [&](const uint8_t* p, size_t len) { return n_ >= len && std::equal(p, p + len, b_); };
    if (starts_with(kCrLfToLf, sizeof kCrLfToLf) || starts_with(kLfToCrLf, sizeof kLfToCrLf))
      return fail(msg::text_mode_corruption, "line endings were converted; transfer the file in binary mode");
    return fail(msg::bad_magic, "the first bytes are not \\x89MBK\\r\\n\\x1a\\n");
  }

  // The header's fields; a newer major is refused before anything else is trusted.
  bool read_header() {
    const ContainerHeader& h = p_.header = load_header(b_);
    const std::string ours = version_string(kFormatMajor, kFormatMinor);
    const std::string theirs = version_string(h.major, h.minor);
    if (h.major > kFormatMajor)
      return fail(msg::newer_major, "file is format " + theirs + ", this reader reads " + ours + " (update microbake)",
                  {{"file_version", theirs}, {"reader_version", ours}});
    if (h.major < 1) return fail(msg::bad_major, "file claims format " + theirs);
    if (h.minor > kFormatMinor)
      findings_.push_back(make_finding(msg::newer_minor, "file is format " + theirs + ", this reader is " + ours,
                                       {{"file_version", theirs}, {"reader_version", ours}}));
    if (h.file_size != n_)
      return fail(msg::file_size_mismatch,
                  "header says " + std::to_string(h.file_size) + " bytes, file has " + std::to_string(n_),
                  {{"recorded", h.file_size}, {"actual", n_}});
    return true;
  }

  // Metadata and section table inside the file, after the header, and apart.
  bool check_header_regions() {
    const ContainerHeader& h = p_.header;
    if (h.metadata_offset < kHeaderSize || !in_bounds(h.metadata_offset, h.metadata_size, n_, &meta_end_))
      return fail(msg::metadata_out_of_bounds,
                  "offset " + std::to_string(h.metadata_offset) + ", size " + std::to_string(h.metadata_size));
    if (h.section_entry_size < kSectionEntrySize)
      return fail(msg::section_entry_too_small, std::to_string(h.section_entry_size) + " bytes");
    if (h.section_count > kMaxSections)
      return fail(msg::too_many_sections,
                  std::to_string(h.section_count) + " (at most " + std::to_string(kMaxSections) + ")");
    table_size_ = uint64_t(h.section_count) * h.section_entry_size;  // both < 2^32: no overflow
    if (h.section_table_offset < kHeaderSize || !in_bounds(h.section_table_offset, table_size_, n_, &table_end_))
      return fail(msg::section_table_out_of_bounds,
                  "offset " + std::to_string(h.section_table_offset) + ", size " + std::to_string(table_size_));
    if (h.metadata_size > 0 && table_size_ > 0 && h.metadata_offset < table_end_ && h.section_table_offset < meta_end_)
      return fail(msg::regions_overlap, "metadata [" + std::to_string(h.metadata_offset) + ", " +
                                            std::to_string(meta_end_) + ") and section table [" +
                                            std::to_string(h.section_table_offset) + ", " + std::to_string(table_end_) +
                                            ")");
    regions_ = {{0, kHeaderSize, "header"},
                {h.metadata_offset, meta_end_, "metadata"},
                {h.section_table_offset, table_end_, "section table"}};
    return true;
  }

  bool check_header_checksum() {
    const ContainerHeader& h = p_.header;
    return header_checksum(b_, h.metadata_offset, h.metadata_size, h.section_table_offset, table_size_) == h.checksum ||
           fail(msg::header_checksum_mismatch, "the header, metadata or section table is damaged");
  }

  // Strict JSON, the required keys with the types readers rely on, and the kind (a file that breaks them is
  // corrupt, not "internal").
  bool parse_metadata() {
    const ContainerHeader& h = p_.header;
    std::string_view text(reinterpret_cast<const char*>(b_ + h.metadata_offset), h.metadata_size);
    if (text.starts_with("\xEF\xBB\xBF"))  // RFC 8259 Sec. 8.1; nlohmann would skip it
      return fail(msg::metadata_not_json, "it starts with a byte-order mark");
    std::string repeated_key;
    nlohmann::json& m = p_.metadata = parse_metadata_json(text, repeated_key);
    if (m.is_discarded() || !m.is_object()) return fail(msg::metadata_not_json, "");
    if (!repeated_key.empty())
      return fail(msg::metadata_duplicate_key, "'" + repeated_key + "'", {{"key", repeated_key}});
    for (const char* key : {"producer", "kind", "inputs", "parameters", "conventions", "statistics"})
      if (!m.contains(key)) return fail(msg::metadata_missing_key, std::string("'") + key + "'", {{"key", key}});
    const auto& producer = m["producer"];
    const bool producer_ok = producer.is_object() && producer.contains("name") && producer["name"].is_string() &&
                             producer.contains("version") && producer["version"].is_string();
    if (!producer_ok)
      return fail(msg::metadata_wrong_type, "'producer' must be {\"name\": string, \"version\": string}",
                  {{"key", "producer"}});
    if (!m["inputs"].is_array())
      return fail(msg::metadata_wrong_type, "'inputs' must be an array", {{"key", "inputs"}});
    for (const char* key : {"parameters", "conventions", "statistics"})
      if (!m[key].is_object())
        return fail(msg::metadata_wrong_type, std::string("'") + key + "' must be an object", {{"key", key}});
    const AssetKind* kind = find_kind(h.kind);
    if (!kind)
      return fail(msg::unknown_kind, "kind id " + std::to_string(h.kind) + std::string(retired_kind_note(h.kind)),
                  {{"kind_id", h.kind}});
    if (!m["kind"].is_string() || m["kind"].get<std::string>() != kind->name)
      return fail(msg::kind_mismatch,
                  "header kind is '" + std::string(kind->name) + "', metadata says " + m["kind"].dump());
    return true;
  }

  // Every entry; all of them are checked (and reported) before the table is refused.
  bool read_section_table() {
    for (uint32_t i = 0; i < p_.header.section_count; ++i) {
      const uint8_t* e = b_ + p_.header.section_table_offset + uint64_t(i) * p_.header.section_entry_size;
      std::optional<SectionInfo> s = read_entry(e, i);
      if (s && place(*s)) p_.sections.push_back(std::move(*s));
    }
    return entries_ok_;
  }

  // A finding about an entry: the table is refused once every entry has been checked.
  bool entry_error(const MessageInfo& m, const std::string& specifics,
                   nlohmann::json details = nlohmann::json::object()) {
    entries_ok_ = fail(m, specifics, std::move(details));
    return false;
  }
  // An entry_error after which the entry is not read further.
  std::nullopt_t skip(const MessageInfo& m, const std::string& specifics,
                      nlohmann::json details = nlohmann::json::object()) {
    entry_error(m, specifics, std::move(details));
    return std::nullopt;
  }

  // Name, element type, rank, zero reserved bytes, shape and byte length of one entry: nullopt (reported) when the
  // entry cannot be read further.
  std::optional<SectionInfo> read_entry(const uint8_t* e, uint32_t index) {
    SectionInfo s;
    const uint8_t* name = e + entry_field::name;
    const uint8_t* nul = std::find(name, name + kSectionNameBytes, uint8_t(0));
    s.name.assign(name, nul);
    const bool padding_zero = std::all_of(nul, name + kSectionNameBytes, [](uint8_t c) { return c == 0; });
    if (!is_valid_section_name(s.name) || !padding_zero)
      return skip(msg::bad_section_name, "section entry " + std::to_string(index), {{"index", index}});
    const std::string sw = "section '" + s.name + "'";
    for (const auto& other : p_.sections)
      if (other.name == s.name) entry_error(msg::duplicate_section, sw);
    const uint32_t type_code = load_le<uint32_t>(e + entry_field::element_type);
    const size_t esize = element_size(type_code);
    if (esize == 0) return skip(msg::unknown_element_type, sw + ": code " + std::to_string(type_code));
    s.type = static_cast<ElementType>(type_code);
    const uint32_t rank = load_le<uint32_t>(e + entry_field::rank);
    if (rank < 1 || rank > kMaxRank) return skip(msg::bad_rank, sw + ": rank " + std::to_string(rank));
    bool reserved_zero =
        std::all_of(e + entry_field::reserved, e + kSectionEntrySize, [](uint8_t c) { return c == 0; });
    uint64_t count = 1;
    bool overflow = false;
    for (uint32_t d = 0; d < kMaxRank; ++d) {
      const uint64_t dim = load_le<uint64_t>(e + entry_field::shape + 8 * d);
      if (d < rank) {
        s.shape.push_back(dim);
        overflow |= __builtin_mul_overflow(count, dim, &count);
      } else if (dim != 0) {
        reserved_zero = false;
      }
    }
    if (!reserved_zero) entry_error(msg::reserved_not_zero, sw);
    uint64_t expected_length = 0;
    if (overflow || __builtin_mul_overflow(count, uint64_t(esize), &expected_length))
      return skip(msg::shape_overflow, sw);
    s.offset = load_le<uint64_t>(e + entry_field::offset);
    s.byte_length = load_le<uint64_t>(e + entry_field::byte_length);
    s.checksum = load_le<uint64_t>(e + entry_field::checksum);
    if (s.byte_length != expected_length)
      return skip(msg::length_mismatch,
                  sw + ": " + std::to_string(s.byte_length) + " bytes, shape needs " + std::to_string(expected_length));
    return s;
  }

  // The section's data inside the file (else false: it is left out), aligned, and apart from every region seen
  // so far, which it joins.
  bool place(const SectionInfo& s) {
    const std::string sw = "section '" + s.name + "'";
    uint64_t end = 0;
    if (!in_bounds(s.offset, s.byte_length, n_, &end))
      return entry_error(msg::section_out_of_bounds, sw + ": offset " + std::to_string(s.offset) + ", length " +
                                                         std::to_string(s.byte_length) + ", file " +
                                                         std::to_string(n_));
    if (s.offset % kSectionAlignment != 0)
      entry_error(msg::misaligned_section, sw + ": offset " + std::to_string(s.offset));
    const Region here{s.offset, end, sw};
    for (const Region& r : regions_)
      if (overlap(r, here)) entry_error(msg::sections_overlap, sw + " overlaps " + r.what);
    regions_.push_back(here);
    return true;
  }

  // Every byte is either in a checksummed region or zero padding between regions, and the file ends with the
  // last region, so no change to a file goes unnoticed.
  bool check_gaps() {
    std::sort(regions_.begin(), regions_.end(), [](const Region& a, const Region& c) { return a.begin < c.begin; });
    uint64_t covered = 0;
    for (const Region& r : regions_) {
      if (r.begin > covered && !std::all_of(b_ + covered, b_ + r.begin, [](uint8_t c) { return c == 0; }))
        return fail(msg::padding_not_zero, "bytes " + std::to_string(covered) + " to " + std::to_string(r.begin));
      covered = std::max(covered, r.end);
    }
    return covered == n_ || fail(msg::trailing_bytes, "the last region ends at byte " + std::to_string(covered) +
                                                          ", the file at " + std::to_string(n_));
  }

  std::span<const uint8_t> bytes_;
  const uint8_t* b_;
  uint64_t n_;
  std::vector<Finding>& findings_;
  ParsedContainer p_;
  uint64_t meta_end_ = 0, table_end_ = 0, table_size_ = 0;
  std::vector<Region> regions_;
  bool entries_ok_ = true;
};

}  // namespace

std::optional<ParsedContainer> parse_container(std::span<const uint8_t> bytes, std::vector<Finding>& findings) {
  return ContainerParser(bytes, findings).parse();
}

void check_sections(const ParsedContainer& p, std::span<const uint8_t> bytes, std::vector<Finding>& findings) {
  for (const SectionInfo& s : p.sections)
    if (checksum_of(bytes.data() + s.offset, s.byte_length) != s.checksum)
      findings.push_back(
          make_finding(msg::section_checksum_mismatch, "section '" + s.name + "'", {{"section", s.name}}));
  const AssetKind* kind = find_kind(p.header.kind);
  if (!kind) return;  // parse_container already reported it
  for (const SectionRule& rule : kind->required_sections) {
    auto it =
        std::find_if(p.sections.begin(), p.sections.end(), [&](const SectionInfo& s) { return s.name == rule.name; });
    if (it == p.sections.end()) {
      findings.push_back(make_finding(msg::missing_required_section, "'" + rule.name + "'", {{"section", rule.name}}));
      continue;
    }
    bool type_ok = std::find(rule.types.begin(), rule.types.end(), it->type) != rule.types.end();
    if (!type_ok || it->shape.size() != rule.rank)
      findings.push_back(make_finding(msg::wrong_section_type, "'" + rule.name + "' is " +
                                                                   std::string(element_name(it->type)) + " of rank " +
                                                                   std::to_string(it->shape.size())));
  }
  for (const SectionInfo& s : p.sections)
    if (kind->knows_section && !kind->knows_section(s.name))
      findings.push_back(make_finding(msg::unknown_section, "'" + s.name + "'", {{"section", s.name}}));
}

Asset Asset::open(const std::filesystem::path& path) { return parse(read_file_bytes(path), path.string()); }

Asset Asset::parse(std::vector<uint8_t> bytes, const std::string& where) {
  Asset a = parse_structure(std::move(bytes), where);
  std::vector<Finding> findings;
  check_kind_invariants(a, findings);
  throw_first_error(findings, where);
  return a;
}

Asset Asset::parse_structure(std::vector<uint8_t> bytes, const std::string& where) {
  std::vector<Finding> findings;
  auto parsed = parse_container(bytes, findings);
  if (parsed) check_sections(*parsed, bytes, findings);
  throw_first_error(findings, where);
  Asset a;
  a.bytes_ = std::move(bytes);
  a.parsed_ = std::move(*parsed);
  a.kind_ = find_kind(a.parsed_.header.kind);
  a.where_ = where;
  return a;
}

const SectionInfo* Asset::find(const std::string& name) const {
  for (const auto& s : parsed_.sections)
    if (s.name == name) return &s;
  return nullptr;
}

const SectionInfo& Asset::section(const std::string& name) const {
  const SectionInfo* s = find(name);
  if (!s) throw Error(ExitCode::invalid_input, "asset lacks section '" + name + "'", where_);
  return *s;
}

std::span<const uint8_t> Asset::bytes_of(const SectionInfo& s) const {
  return {bytes_.data() + s.offset, s.byte_length};
}

Error Asset::type_error(const SectionInfo& s, ElementType wanted) const {
  return Error(ExitCode::invalid_input,
               "section '" + s.name + "' holds " + std::string(element_name(s.type)) + ", expected " +
                   std::string(element_name(wanted)),
               where_);
}

std::vector<float> Asset::read_as_float(const std::string& name) const {
  const SectionInfo& s = section(name);
  switch (s.type) {
    case ElementType::f32:
      return read<float>(name);
    case ElementType::f64: {
      auto d = read<double>(name);
      return std::vector<float>(d.begin(), d.end());
    }
    case ElementType::f16: {
      auto h = read<Imath::half>(name);
      std::vector<float> out(h.size());
      for (size_t i = 0; i < h.size(); ++i) out[i] = float(h[i]);
      return out;
    }
    default:
      throw type_error(s, ElementType::f32);
  }
}

}  // namespace mbk
