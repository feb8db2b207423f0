// Every finding `microbake validate` can report, in one table (formats/SPEC.md, "Validation findings").
// Ids are stable and grouped by thousand: 1xxx container, 2xxx header and metadata, 3xxx sections, and
// 10000 + 1000 * kind id for the invariants of each asset kind. Never reuse or renumber an id.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace mbk {

enum class Severity { error, warning };
std::string_view severity_name(Severity s);

struct MessageInfo {
  int id;
  Severity severity;
  std::string_view title;
};

struct Finding {
  int id = 0;
  Severity severity = Severity::error;
  std::string message;  // title, then ": " and the specifics
  nlohmann::json details = nlohmann::json::object();
};

Finding make_finding(const MessageInfo& info, const std::string& specifics,
                     nlohmann::json details = nlohmann::json::object());

namespace msg {
// 1xxx: the file as a whole
inline constexpr MessageInfo file_too_small{1001, Severity::error, "file too small to hold an .mbk header"};
inline constexpr MessageInfo bad_magic{1002, Severity::error, "not an .mbk file (bad magic)"};
inline constexpr MessageInfo text_mode_corruption{1003, Severity::error,
                                                  "file damaged by a text-mode line-ending conversion"};
inline constexpr MessageInfo file_size_mismatch{
    1004, Severity::error, "file size differs from the size recorded in the header (truncated or extended)"};
inline constexpr MessageInfo padding_not_zero{1005, Severity::error, "padding between regions is not zero"};
// Reported by `validate` for a file it cannot read at all (missing, a folder, no permission): exit 2, not 3.
inline constexpr MessageInfo file_unreadable{1006, Severity::error, "file cannot be read"};
inline constexpr MessageInfo trailing_bytes{1007, Severity::error,
                                            "bytes after the end of the last region (the file must end there)"};
// 2xxx: header and metadata
inline constexpr MessageInfo newer_major{2001, Severity::error, "asset written by a newer major format version"};
inline constexpr MessageInfo bad_major{2002, Severity::error, "invalid major format version"};
inline constexpr MessageInfo newer_minor{2003, Severity::warning,
                                         "asset written by a newer minor format version; its additions are ignored"};
inline constexpr MessageInfo header_checksum_mismatch{2004, Severity::error,
                                                      "header/metadata/section-table checksum mismatch"};
inline constexpr MessageInfo metadata_out_of_bounds{2005, Severity::error, "metadata block out of bounds"};
inline constexpr MessageInfo section_table_out_of_bounds{2006, Severity::error, "section table out of bounds"};
inline constexpr MessageInfo section_entry_too_small{2007, Severity::error,
                                                     "section entry size smaller than 128 bytes"};
inline constexpr MessageInfo too_many_sections{2008, Severity::error, "too many sections"};
inline constexpr MessageInfo metadata_not_json{2009, Severity::error, "metadata is not a UTF-8 JSON object"};
inline constexpr MessageInfo metadata_missing_key{2010, Severity::error, "metadata lacks a required key"};
inline constexpr MessageInfo unknown_kind{2011, Severity::error, "unknown asset kind"};
inline constexpr MessageInfo kind_mismatch{2012, Severity::error, "metadata kind differs from the header's kind id"};
inline constexpr MessageInfo regions_overlap{2013, Severity::error, "header, metadata and section table overlap"};
inline constexpr MessageInfo metadata_wrong_type{2014, Severity::error,
                                                 "a required metadata key has the wrong JSON type"};
inline constexpr MessageInfo metadata_duplicate_key{2015, Severity::error,
                                                    "metadata repeats a key within one JSON object"};
// 3xxx: sections
inline constexpr MessageInfo bad_section_name{3001, Severity::error, "invalid section name"};
inline constexpr MessageInfo duplicate_section{3002, Severity::error, "duplicate section name"};
inline constexpr MessageInfo unknown_element_type{3003, Severity::error, "unknown element type"};
inline constexpr MessageInfo bad_rank{3004, Severity::error, "section rank outside 1..6"};
inline constexpr MessageInfo shape_overflow{3005, Severity::error, "section shape product overflows"};
inline constexpr MessageInfo length_mismatch{3006, Severity::error,
                                             "section byte length differs from shape x element size"};
inline constexpr MessageInfo section_out_of_bounds{3007, Severity::error, "section data out of bounds"};
inline constexpr MessageInfo misaligned_section{3008, Severity::error, "section data not 64-byte aligned"};
inline constexpr MessageInfo sections_overlap{3009, Severity::error, "section data overlaps another region"};
inline constexpr MessageInfo section_checksum_mismatch{3010, Severity::error, "section checksum mismatch"};
inline constexpr MessageInfo reserved_not_zero{3011, Severity::error,
                                               "reserved bytes or unused shape entries are not zero"};
inline constexpr MessageInfo missing_required_section{3012, Severity::error,
                                                      "a section required by the asset kind is missing"};
inline constexpr MessageInfo wrong_section_type{3013, Severity::error,
                                                "section has the wrong element type or rank for its kind"};
inline constexpr MessageInfo unknown_section{3014, Severity::warning,
                                             "section unknown to this asset kind (ignored by readers)"};
// 11xxx: kind 1, `mip` (normal MIP pyramid)
inline constexpr MessageInfo mip_non_finite{11001, Severity::error, "mip: non-finite value"};
inline constexpr MessageInfo mip_level_shape{11002, Severity::error, "mip: level sizes do not follow the halving rule"};
inline constexpr MessageInfo mip_length_exceeds_one{11003, Severity::error, "mip: averaged normal longer than 1"};
inline constexpr MessageInfo mip_level0_not_unit{11004, Severity::error, "mip: finest-level normal not unit length"};
inline constexpr MessageInfo mip_parent_not_mean{11005, Severity::error,
                                                 "mip: texel is not the mean of the finest normals it covers"};
inline constexpr MessageInfo mip_bad_parameters{11006, Severity::error,
                                                "mip: parameters missing or inconsistent with the sections"};
// 20xxx: kind 10, `lut` (standardization knots of glints; 12xxx were the retired kind 2's)
inline constexpr MessageInfo lut_non_finite{20001, Severity::error, "lut: non-finite value"};
inline constexpr MessageInfo lut_bad_parameters{20002, Severity::error,
                                                "lut: parameters missing or out of range (size in 2..65536)"};
inline constexpr MessageInfo lut_section_shape{20003, Severity::error,
                                               "lut: section shape does not match the parameters"};
inline constexpr MessageInfo lut_bad_domain{20004, Severity::error, "lut: a one-knot (constant) channel with z != 0"};
inline constexpr MessageInfo lut_not_monotone{20005, Severity::error, "lut: knots not strictly increasing in x or z"};
// 13xxx: kind 3, `rmq` (RMQ min/max tables of glints)
inline constexpr MessageInfo rmq_bad_parameters{
    13001, Severity::error, "rmq: parameters missing or inconsistent (width, height, patch, levels, bits)"};
inline constexpr MessageInfo rmq_section_shape{13002, Severity::error,
                                               "rmq: section type or shape does not match the parameters"};
inline constexpr MessageInfo rmq_bad_range{13003, Severity::error, "rmq: quantization range not finite or lo > hi"};
inline constexpr MessageInfo rmq_min_above_max{13004, Severity::error, "rmq: an entry's min is above its max"};
inline constexpr MessageInfo rmq_not_nested{13005, Severity::error,
                                            "rmq: an entry does not contain its four children of the level below"};
// 14xxx: kind 4, `sh` (SH NDF pyramids)
inline constexpr MessageInfo sh_bad_parameters{
    14001, Severity::error, "sh: parameters missing or inconsistent (width, height, levels, order, precision, window)"};
inline constexpr MessageInfo sh_section_shape{14002, Severity::error,
                                              "sh: section type or shape does not match the parameters"};
inline constexpr MessageInfo sh_non_finite{14003, Severity::error, "sh: non-finite value"};
inline constexpr MessageInfo sh_normal_not_unit{14004, Severity::error, "sh: finest-level normal not unit length"};
inline constexpr MessageInfo sh_dc_wrong{14005, Severity::error,
                                         "sh: g_00 is not 1 / (2 sqrt(pi)) (the NDF does not integrate to 1)"};
inline constexpr MessageInfo sh_coefficient_out_of_bounds{
    14006, Severity::error, "sh: coefficient larger than the basis function's maximum (not a mean of Y_lm)"};
inline constexpr MessageInfo sh_band1_not_mean_normal{
    14007, Severity::error, "sh: band-1 coefficients are not sqrt(3 / (4 pi)) times the mean of the finest normals"};
inline constexpr MessageInfo sh_bad_window{14008, Severity::error,
                                           "sh: window factors not in (0, 1], not non-increasing, or window[0] != 1"};
// 15xxx: kind 5, `vmf` (vMF mixture MIP maps)
inline constexpr MessageInfo vmf_bad_parameters{
    15001, Severity::error, "vmf: parameters missing or inconsistent (width, height, levels, lobes, kappa_max, align)"};
inline constexpr MessageInfo vmf_section_shape{15002, Severity::error,
                                               "vmf: section type or shape does not match the parameters"};
inline constexpr MessageInfo vmf_non_finite{15003, Severity::error, "vmf: non-finite value"};
inline constexpr MessageInfo vmf_amplitudes_not_normalised{
    15004, Severity::error, "vmf: a lobe amplitude is negative or a texel's amplitudes do not sum to 1"};
inline constexpr MessageInfo vmf_mean_too_long{15005, Severity::error,
                                               "vmf: a lobe's mean resultant r is longer than 1 (|alpha r| > alpha)"};
inline constexpr MessageInfo vmf_finest_not_single_lobe{
    15006, Severity::error, "vmf: a finest-level texel is not one lobe of amplitude 1 at a unit normal"};
inline constexpr MessageInfo vmf_moment_not_mean_normal{
    15007, Severity::error,
    "vmf: a texel's first moment sum_j alpha_j r_j is not the mean of the finest normals it covers (unaligned fits)"};
inline constexpr MessageInfo vmf_empty_lobe_not_zero{15008, Severity::error,
                                                     "vmf: an empty lobe (alpha = 0) carries a direction or features"};
// 17xxx: kind 7, `colormap` (prefiltered colour-map tables)
inline constexpr MessageInfo colormap_non_finite{17001, Severity::error, "colormap: non-finite value"};
inline constexpr MessageInfo colormap_bad_parameters{
    17002, Severity::error,
    "colormap: parameters missing or out of range (width, height in 2..8192, mean_min < mean_max, sigma_max > 0)"};
inline constexpr MessageInfo colormap_section_shape{17003, Severity::error,
                                                    "colormap: section shape does not match the parameters"};
inline constexpr MessageInfo colormap_bad_knots{17004, Severity::error,
                                                "colormap: knots decrease, or more than two knots share a position"};
inline constexpr MessageInfo colormap_row0_not_map{17005, Severity::error,
                                                   "colormap: the sigma = 0 row is not the colour map itself"};
inline constexpr MessageInfo colormap_outside_hull{
    17006, Severity::error, "colormap: entry outside the colour map's range (a Gaussian average cannot leave it)"};
inline constexpr MessageInfo colormap_not_convolution{
    17007, Severity::error, "colormap: entry differs from the Gaussian convolution of the colour map"};
// 18xxx: kind 8, `moments` (moment pyramids of drivers)
inline constexpr MessageInfo moments_non_finite{18001, Severity::error, "moments: non-finite value"};
inline constexpr MessageInfo moments_bad_parameters{
    18002, Severity::error, "moments: parameters missing or inconsistent (width, height, levels, finite shift)"};
inline constexpr MessageInfo moments_level_shape{18003, Severity::error,
                                                 "moments: level sizes do not follow the halving rule"};
inline constexpr MessageInfo moments_level0_not_square{
    18004, Severity::error, "moments: a finest texel's second moment is not the square of its first"};
inline constexpr MessageInfo moments_negative_variance{18005, Severity::error,
                                                       "moments: a texel's second moment is below its mean squared"};
inline constexpr MessageInfo moments_parent_not_mean{18006, Severity::error,
                                                     "moments: texel is not the mean of the finest texels it covers"};
// 16xxx: kind 6, `crease` (discontinuity signatures, distance and gradient maps)
inline constexpr MessageInfo crease_bad_parameters{16001, Severity::error,
                                                   "crease: parameters missing or out of range (width, height)"};
inline constexpr MessageInfo crease_section_shape{16002, Severity::error,
                                                  "crease: section type or shape does not match the parameters"};
inline constexpr MessageInfo crease_non_finite{16003, Severity::error, "crease: non-finite value"};
inline constexpr MessageInfo crease_bad_crossing{16004, Severity::error,
                                                 "crease: edge crossing neither -1 (none) nor in [1/1024, 1 - 1/1024]"};
inline constexpr MessageInfo crease_bad_segments{
    16005, Severity::error,
    "crease: cell segment word not an allowed configuration (unknown bits, more than two segments, a segment "
    "ending on an edge without a crossing, or a direction bit without its segment)"};
inline constexpr MessageInfo crease_negative_distance{16006, Severity::error, "crease: negative distance"};
inline constexpr MessageInfo crease_gradient_not_unit{16007, Severity::error, "crease: gradient is not a unit vector"};
inline constexpr MessageInfo crease_bad_side{16008, Severity::error, "crease: side is neither +1 nor -1"};
inline constexpr MessageInfo crease_bad_normal{16009, Severity::error,
                                               "crease: normal is not a unit vector in the upper hemisphere"};
inline constexpr MessageInfo crease_bad_junction{
    16010, Severity::error,
    "crease: junction record not allowed (cells not increasing or out of range, a junction word without its record "
    "or a record without its word, fewer than two spokes, a spoke on an edge without a crossing, a direction bit "
    "without its spoke, or the point not inside the cell's edge points)"};
// 19xxx: kind 9, `graph` (exemplar-graph analysis for multiscale synthesis)
inline constexpr MessageInfo graph_bad_parameters{19001, Severity::error,
                                                  "graph: parameters or graph metadata missing or inconsistent"};
inline constexpr MessageInfo graph_section_shape{19002, Severity::error,
                                                 "graph: section type or shape does not match the parameters"};
inline constexpr MessageInfo graph_non_finite{19003, Severity::error, "graph: non-finite stack or transfer value"};
inline constexpr MessageInfo graph_bad_candidate{
    19004, Severity::error, "graph: candidate out of range or not in the admissible levels of its stack level"};
inline constexpr MessageInfo graph_bad_transfer{
    19005, Severity::error,
    "graph: transfer offset not zero within one level of one exemplar or where there is no candidate"};
inline constexpr MessageInfo graph_bad_pca{19006, Severity::error,
                                           "graph: synthesis PCA mean not finite or basis not orthonormal"};
// 21xxx: kind 11, `histogram` (adaptive bins and integral images of per-bin counts: the exact binned P-NDF)
inline constexpr MessageInfo histogram_bad_parameters{
    21001, Severity::error,
    "histogram: parameters missing or out of range (width, height, theta_bins, theta_bins_requested, phi_bins, "
    "method, theta_binning)"};
inline constexpr MessageInfo histogram_section_shape{21002, Severity::error,
                                                     "histogram: section type or shape does not match the parameters"};
inline constexpr MessageInfo histogram_bad_theta_edges{21003, Severity::error,
                                                       "histogram: theta edges do not rise strictly from 0 to pi/2"};
inline constexpr MessageInfo histogram_bad_theta_centres{
    21004, Severity::error,
    "histogram: a theta centre lies outside its bin, or an interior edge is not the midpoint of its two centres"};
inline constexpr MessageInfo histogram_bad_phi_edges{21005, Severity::error,
                                                     "histogram: phi edges are not the uniform 2 pi i / N"};
inline constexpr MessageInfo histogram_border_not_zero{
    21006, Severity::error, "histogram: the count table's first row or first column is not zero"};
inline constexpr MessageInfo histogram_negative_count{
    21007, Severity::error, "histogram: a footprint's corners give a negative count for a bin"};
inline constexpr MessageInfo histogram_count_not_area{
    21008, Severity::error, "histogram: a footprint's bin counts do not sum to its area in texels"};
// 22xxx: kind 12, `neural_histogram` (adaptive bins, a feature pyramid and MLPs: the neural binned P-NDF)
inline constexpr MessageInfo neural_histogram_bad_parameters{
    22001, Severity::error,
    "neural_histogram: parameters missing or out of range (width, height, method, theta_bins, theta_bins_requested, "
    "phi_bins, theta_binning, features, hidden, levels, min_footprint, iterations, batch, seed, training_seed)"};
inline constexpr MessageInfo neural_histogram_section_shape{
    22002, Severity::error, "neural_histogram: section type or shape does not match the parameters"};
inline constexpr MessageInfo neural_histogram_bad_theta_edges{
    22003, Severity::error, "neural_histogram: theta edges do not rise strictly from 0 to pi/2"};
inline constexpr MessageInfo neural_histogram_bad_theta_centres{
    22004, Severity::error,
    "neural_histogram: a theta centre lies outside its bin, or an interior edge is not the midpoint of its two "
    "centres"};
inline constexpr MessageInfo neural_histogram_bad_texel_bin{
    22005, Severity::error, "neural_histogram: a texel's bin index is not below theta_bins x phi_bins"};
inline constexpr MessageInfo neural_histogram_non_finite{
    22006, Severity::error, "neural_histogram: a feature or network parameter is not finite"};
}  // namespace msg

// All of the above, for documentation and the uniqueness test.
std::span<const MessageInfo> all_messages();

}  // namespace mbk
