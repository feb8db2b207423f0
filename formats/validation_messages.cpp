// The table of validation findings (see validation_messages.h).
#include "formats/validation_messages.h"

#include <array>

namespace mbk {

std::string_view severity_name(Severity s) { return s == Severity::error ? "error" : "warning"; }

Finding make_finding(const MessageInfo& info, const std::string& specifics, nlohmann::json details) {
  Finding f;
  f.id = info.id;
  f.severity = info.severity;
  f.message = specifics.empty() ? std::string(info.title) : std::string(info.title) + ": " + specifics;
  f.details = std::move(details);
  return f;
}

std::span<const MessageInfo> all_messages() {
  using namespace msg;
  static const std::array kAll = {
      file_too_small,
      bad_magic,
      text_mode_corruption,
      file_size_mismatch,
      padding_not_zero,
      file_unreadable,
      trailing_bytes,
      newer_major,
      bad_major,
      newer_minor,
      header_checksum_mismatch,
      metadata_out_of_bounds,
      section_table_out_of_bounds,
      section_entry_too_small,
      too_many_sections,
      metadata_not_json,
      metadata_missing_key,
      unknown_kind,
      kind_mismatch,
      regions_overlap,
      metadata_wrong_type,
      metadata_duplicate_key,
      bad_section_name,
      duplicate_section,
      unknown_element_type,
      bad_rank,
      shape_overflow,
      length_mismatch,
      section_out_of_bounds,
      misaligned_section,
      sections_overlap,
      section_checksum_mismatch,
      reserved_not_zero,
      missing_required_section,
      wrong_section_type,
      unknown_section,
      mip_non_finite,
      mip_level_shape,
      mip_length_exceeds_one,
      mip_level0_not_unit,
      mip_parent_not_mean,
      mip_bad_parameters,
      lut_non_finite,
      lut_bad_parameters,
      lut_section_shape,
      lut_bad_domain,
      lut_not_monotone,
      rmq_bad_parameters,
      rmq_section_shape,
      rmq_bad_range,
      rmq_min_above_max,
      rmq_not_nested,
      sh_bad_parameters,
      sh_section_shape,
      sh_non_finite,
      sh_normal_not_unit,
      sh_dc_wrong,
      sh_coefficient_out_of_bounds,
      sh_band1_not_mean_normal,
      sh_bad_window,
      vmf_bad_parameters,
      vmf_section_shape,
      vmf_non_finite,
      vmf_amplitudes_not_normalised,
      vmf_mean_too_long,
      vmf_finest_not_single_lobe,
      vmf_moment_not_mean_normal,
      vmf_empty_lobe_not_zero,
      colormap_non_finite,
      colormap_bad_parameters,
      colormap_section_shape,
      colormap_bad_knots,
      colormap_row0_not_map,
      colormap_outside_hull,
      colormap_not_convolution,
      moments_non_finite,
      moments_bad_parameters,
      moments_level_shape,
      moments_level0_not_square,
      moments_negative_variance,
      moments_parent_not_mean,
      crease_bad_parameters,
      crease_section_shape,
      crease_non_finite,
      crease_bad_crossing,
      crease_bad_segments,
      crease_negative_distance,
      crease_gradient_not_unit,
      crease_bad_side,
      crease_bad_normal,
      graph_bad_parameters,
      graph_section_shape,
      graph_non_finite,
      graph_bad_candidate,
      graph_bad_transfer,
      graph_bad_pca,
      histogram_bad_parameters,
      histogram_section_shape,
      histogram_bad_theta_edges,
      histogram_bad_theta_centres,
      histogram_bad_phi_edges,
      histogram_border_not_zero,
      histogram_negative_count,
      histogram_count_not_area,
  };
  return kAll;
}

}  // namespace mbk
