#pragma once
// The scene's [output] table: what a solve writes beside the small CSV and JSON files
// (docs/interface.md, "Output files").
#include <array>
#include <string_view>
#include <utility>

#include "stcontact/options/option_fields.hpp"

namespace stc {

/// Where the frames go: solution.h5 indexed by solution.xdmf (src/io/solution_file.hpp), or a
/// ParaView collection solution.pvd of vtu/ files (src/io/vtu_writer.hpp).
enum class OutputFormat { Hdf5, Vtu };
inline constexpr std::array<std::pair<std::string_view, OutputFormat>, 2> kOutputFormats = {{
    {"hdf5", OutputFormat::Hdf5},
    {"vtu", OutputFormat::Vtu},
}};

/// Floating-point type of the frames' fields.
enum class FieldPrecision { Float32, Float64 };
inline constexpr std::array<std::pair<std::string_view, FieldPrecision>, 2> kFieldPrecisions = {{
    {"float32", FieldPrecision::Float32},
    {"float64", FieldPrecision::Float64},
}};

/// When contact.csv (one text row per contact node and instant) is written: "auto" while it stays
/// small (io/contact_tables.hpp, kSmallContactCsvBytes: the seed scene's is 3 MB), "always", "never".
/// solution.h5 holds the same histories as arrays in any case.
enum class ContactCsv { Auto, Always, Never };
inline constexpr std::array<std::pair<std::string_view, ContactCsv>, 3> kContactCsvChoices = {{
    {"auto", ContactCsv::Auto},
    {"always", ContactCsv::Always},
    {"never", ContactCsv::Never},
}};

/// [output]: what to write beside the small CSV/JSON files. Each key declared, defaulted and checked
/// in fields() (src/options/option_fields.hpp), which the scene reader walks.
struct OutputSpec {
  bool frames = true;                        ///< write frames: displacement, stress and contact fields at output instants
  OutputFormat format = OutputFormat::Hdf5;  ///< solution.h5 + solution.xdmf, or solution.pvd + vtu/
  /// Write the frame of every k-th instant (the last one always), >= 1; 0 ("auto"): every instant
  /// while the frames stay within 16 MB in single precision, else the smallest stride that keeps them
  /// there (io/frame_fields.hpp, autoFrameStride).
  int frame_stride = 0;
  /// Float32 (ParaView renders in single precision; half the size of Float64) or Float64. The exact
  /// interface histories are in solution.h5 (double precision) whatever this says.
  FieldPrecision field_precision = FieldPrecision::Float32;
  ContactCsv contact_csv = ContactCsv::Auto;  ///< contact.csv: "auto" (when small), "always", "never"

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("frames", o.frames, anyFlag());
    visit("format", o.format, Keywords<OutputFormat>(kOutputFormats));
    visit("frame_stride", o.frame_stride, atLeast(0));
    visit("field_precision", o.field_precision, Keywords<FieldPrecision>(kFieldPrecisions));
    visit("contact_csv", o.contact_csv, Keywords<ContactCsv>(kContactCsvChoices));
  }
};

}  // namespace stc
