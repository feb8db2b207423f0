// The .mbk reader: structural parsing with findings, checksum verification, and the Asset accessor
// (formats/SPEC.md). Every offset, size and product is checked for overflow and bounds before use.
#include "formats/asset.h"

#include <Imath/half.h>

#include <algorithm>
#include <cstring>

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

bool in_bounds(uint64_t offset, uint64_t size, uint64_t total, uint64_t* end) {
  if (__builtin_add_overflow(offset, size, end)) return false;
  return *end <= total;
}

}  // namespace

std::optional<ParsedContainer> parse_container(std::span<const uint8_t> bytes, std::vector<Finding>& findings) {
  const uint64_t n = bytes.size();
  auto fail = [&](const MessageInfo& m, const std::string& s, nlohmann::json d = nlohmann::json::object()) {
    findings.push_back(make_finding(m, s, std::move(d)));
    return std::nullopt;
  };
  // Magic first, so that a short non-.mbk file is reported as "not an .mbk file".
  const size_t magic_n = std::min<size_t>(n, kMagic.size());
  if (!std::equal(bytes.begin(), bytes.begin() + magic_n, kMagic.begin())) {
    // CR LF -> LF turns "\r\n\x1a\n" into "\n\x1a\n"; LF -> CR LF turns it into "\r\r\n\x1a\r\n".
    static const uint8_t kCrLfToLf[] = {0x89, 'M', 'B', 'K', '\n', 0x1A, '\n'};
    static const uint8_t kLfToCrLf[] = {0x89, 'M', 'B', 'K', '\r', '\r', '\n', 0x1A, '\r', '\n'};
    auto starts_with = [&](const uint8_t* p, size_t len) { return n >= len && std::equal(p, p + len, bytes.begin()); };
    if (starts_with(kCrLfToLf, sizeof kCrLfToLf) || starts_with(kLfToCrLf, sizeof kLfToCrLf))
      return fail(msg::text_mode_corruption, "line endings were converted; transfer the file in binary mode");
    return fail(msg::bad_magic, "the first bytes are not \\x89MBK\\r\\n\\x1a\\n");
  }
  if (n < kHeaderSize) return fail(msg::file_too_small, std::to_string(n) + " bytes, the header alone needs 64");

  ParsedContainer p;
  ContainerHeader& h = p.header;
  const uint8_t* b = bytes.data();
  h.major = load_le<uint16_t>(b + 8);
  h.minor = load_le<uint16_t>(b + 10);
  h.kind = load_le<uint32_t>(b + 12);
  h.file_size = load_le<uint64_t>(b + 16);
  h.metadata_offset = load_le<uint64_t>(b + 24);
  h.metadata_size = load_le<uint64_t>(b + 32);
  h.section_table_offset = load_le<uint64_t>(b + 40);
  h.section_count = load_le<uint32_t>(b + 48);
  h.section_entry_size = load_le<uint32_t>(b + 52);
  h.checksum = load_le<uint64_t>(b + 56);

  const std::string ours = version_string(kFormatMajor, kFormatMinor);
  const std::string theirs = version_string(h.major, h.minor);
  if (h.major > kFormatMajor)
    return fail(msg::newer_major, "file is format " + theirs + ", this reader reads " + ours + " (update microbake)",
                {{"file_version", theirs}, {"reader_version", ours}});
  if (h.major < 1) return fail(msg::bad_major, "file claims format " + theirs);
  if (h.minor > kFormatMinor)
    findings.push_back(make_finding(msg::newer_minor, "file is format " + theirs + ", this reader is " + ours,
                                    {{"file_version", theirs}, {"reader_version", ours}}));
  if (h.file_size != n)
    return fail(msg::file_size_mismatch,
                "header says " + std::to_string(h.file_size) + " bytes, file has " + std::to_string(n),
                {{"recorded", h.file_size}, {"actual", n}});

  uint64_t meta_end = 0, table_end = 0, table_size = 0;
  if (h.metadata_offset < kHeaderSize || !in_bounds(h.metadata_offset, h.metadata_size, n, &meta_end))
    return fail(msg::metadata_out_of_bounds,
                "offset " + std::to_string(h.metadata_offset) + ", size " + std::to_string(h.metadata_size));
  if (h.section_entry_size < kSectionEntrySize)
    return fail(msg::section_entry_too_small, std::to_string(h.section_entry_size) + " bytes");
  if (h.section_count > kMaxSections)
    return fail(msg::too_many_sections,
                std::to_string(h.section_count) + " (at most " + std::to_string(kMaxSections) + ")");
  table_size = uint64_t(h.section_count) * h.section_entry_size;  // both < 2^32: no overflow
  if (h.section_table_offset < kHeaderSize || !in_bounds(h.section_table_offset, table_size, n, &table_end))
    return fail(msg::section_table_out_of_bounds,
                "offset " + std::to_string(h.section_table_offset) + ", size " + std::to_string(table_size));
  if (h.metadata_size > 0 && table_size > 0 && h.metadata_offset < table_end && h.section_table_offset < meta_end)
    return fail(msg::regions_overlap, "metadata [" + std::to_string(h.metadata_offset) + ", " +
                                          std::to_string(meta_end) + ") and section table [" +
                                          std::to_string(h.section_table_offset) + ", " + std::to_string(table_end) +
                                          ")");

  if (header_checksum(b, h.metadata_offset, h.metadata_size, h.section_table_offset, table_size) != h.checksum)
    return fail(msg::header_checksum_mismatch, "the header, metadata or section table is damaged");

  std::string_view meta_text(reinterpret_cast<const char*>(b + h.metadata_offset), h.metadata_size);
  p.metadata = nlohmann::json::parse(meta_text, nullptr, /*allow_exceptions=*/false);
  if (p.metadata.is_discarded() || !p.metadata.is_object()) return fail(msg::metadata_not_json, "");
  for (const char* key : {"producer", "kind", "inputs", "parameters", "conventions", "statistics"})
    if (!p.metadata.contains(key)) return fail(msg::metadata_missing_key, std::string("'") + key + "'", {{"key", key}});
  // Readers (info, the evaluator) rely on these shapes; a file that breaks them is corrupt, not "internal".
  const auto& producer = p.metadata["producer"];
  const bool producer_ok = producer.is_object() && producer.contains("name") && producer["name"].is_string() &&
                           producer.contains("version") && producer["version"].is_string();
  if (!producer_ok)
    return fail(msg::metadata_wrong_type, "'producer' must be {\"name\": string, \"version\": string}",
                {{"key", "producer"}});
  if (!p.metadata["inputs"].is_array())
    return fail(msg::metadata_wrong_type, "'inputs' must be an array", {{"key", "inputs"}});
  for (const char* key : {"parameters", "conventions", "statistics"})
    if (!p.metadata[key].is_object())
      return fail(msg::metadata_wrong_type, std::string("'") + key + "' must be an object", {{"key", key}});
  const AssetKind* kind = find_kind(h.kind);
  if (!kind)
    return fail(msg::unknown_kind, "kind id " + std::to_string(h.kind) + std::string(retired_kind_note(h.kind)),
                {{"kind_id", h.kind}});
  if (!p.metadata["kind"].is_string() || p.metadata["kind"].get<std::string>() != kind->name)
    return fail(msg::kind_mismatch,
                "header kind is '" + std::string(kind->name) + "', metadata says " + p.metadata["kind"].dump());

  std::vector<Region> regions = {{0, kHeaderSize, "header"},
                                 {h.metadata_offset, meta_end, "metadata"},
                                 {h.section_table_offset, table_end, "section table"}};
  bool ok = true;
  for (uint32_t i = 0; i < h.section_count; ++i) {
    const uint8_t* e = b + h.section_table_offset + uint64_t(i) * h.section_entry_size;
    const std::string where = "section entry " + std::to_string(i);
    SectionInfo s;
    const uint8_t* nul = std::find(e, e + kSectionNameBytes, uint8_t(0));
    s.name.assign(e, nul);
    bool padding_zero = std::all_of(nul, e + kSectionNameBytes, [](uint8_t c) { return c == 0; });
    if (!is_valid_section_name(s.name) || !padding_zero) {
      findings.push_back(make_finding(msg::bad_section_name, where, {{"index", i}}));
      ok = false;
      continue;
    }
    const std::string sw = "section '" + s.name + "'";
    for (const auto& other : p.sections)
      if (other.name == s.name) {
        findings.push_back(make_finding(msg::duplicate_section, sw));
        ok = false;
      }
    const uint32_t type_code = load_le<uint32_t>(e + 32);
    const size_t esize = element_size(type_code);
    if (esize == 0) {
      findings.push_back(make_finding(msg::unknown_element_type, sw + ": code " + std::to_string(type_code)));
      ok = false;
      continue;
    }
    s.type = static_cast<ElementType>(type_code);
    const uint32_t rank = load_le<uint32_t>(e + 36);
    if (rank < 1 || rank > kMaxRank) {
      findings.push_back(make_finding(msg::bad_rank, sw + ": rank " + std::to_string(rank)));
      ok = false;
      continue;
    }
    bool reserved_zero = std::all_of(e + 112, e + kSectionEntrySize, [](uint8_t c) { return c == 0; });
    uint64_t count = 1;
    bool overflow = false;
    for (uint32_t d = 0; d < kMaxRank; ++d) {
      uint64_t dim = load_le<uint64_t>(e + 40 + 8 * d);
      if (d < rank) {
        s.shape.push_back(dim);
        overflow |= __builtin_mul_overflow(count, dim, &count);
      } else if (dim != 0) {
        reserved_zero = false;
      }
    }
    if (!reserved_zero) {
      findings.push_back(make_finding(msg::reserved_not_zero, sw));
      ok = false;
    }
    uint64_t expected_length = 0;
    if (overflow || __builtin_mul_overflow(count, uint64_t(esize), &expected_length)) {
      findings.push_back(make_finding(msg::shape_overflow, sw));
      ok = false;
      continue;
    }
    s.offset = load_le<uint64_t>(e + 88);
    s.byte_length = load_le<uint64_t>(e + 96);
    s.checksum = load_le<uint64_t>(e + 104);
    if (s.byte_length != expected_length) {
      findings.push_back(make_finding(
          msg::length_mismatch,
          sw + ": " + std::to_string(s.byte_length) + " bytes, shape needs " + std::to_string(expected_length)));
      ok = false;
      continue;
    }
    uint64_t end = 0;
    if (!in_bounds(s.offset, s.byte_length, n, &end)) {
      findings.push_back(make_finding(msg::section_out_of_bounds, sw + ": offset " + std::to_string(s.offset) +
                                                                      ", length " + std::to_string(s.byte_length) +
                                                                      ", file " + std::to_string(n)));
      ok = false;
      continue;
    }
    if (s.offset % kSectionAlignment != 0) {
      findings.push_back(make_finding(msg::misaligned_section, sw + ": offset " + std::to_string(s.offset)));
      ok = false;
    }
    for (const Region& r : regions)
      if (s.byte_length > 0 && r.end > r.begin && s.offset < r.end && r.begin < end) {
        findings.push_back(make_finding(msg::sections_overlap, sw + " overlaps " + r.what));
        ok = false;
      }
    regions.push_back({s.offset, end, sw});
    p.sections.push_back(std::move(s));
  }
  if (!ok) return std::nullopt;
  // Every byte is either in a checksummed region or zero padding, so no change to a file goes unnoticed.
  std::sort(regions.begin(), regions.end(), [](const Region& a, const Region& c) { return a.begin < c.begin; });
  uint64_t covered = 0;
  for (const Region& r : regions) {
    if (r.begin > covered && !std::all_of(b + covered, b + r.begin, [](uint8_t c) { return c == 0; }))
      return fail(msg::padding_not_zero, "bytes " + std::to_string(covered) + " to " + std::to_string(r.begin));
    covered = std::max(covered, r.end);
  }
  if (covered < n && !std::all_of(b + covered, b + n, [](uint8_t c) { return c == 0; }))
    return fail(msg::padding_not_zero, "bytes " + std::to_string(covered) + " to " + std::to_string(n));
  return p;
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
