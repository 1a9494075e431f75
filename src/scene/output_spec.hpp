#pragma once
// The scene's [output] table: what a solve writes beside the CSV and JSON files
// (docs/interface.md, "Output files").
#include <array>
#include <string_view>
#include <utility>

#include "stcontact/options/option_fields.hpp"

namespace stc {

/// Floating-point type of the .vtu arrays (src/io/vtu_writer.hpp).
enum class VtuPrecision { Float32, Float64 };
inline constexpr std::array<std::pair<std::string_view, VtuPrecision>, 2> kVtuPrecisions = {{
    {"float32", VtuPrecision::Float32},
    {"float64", VtuPrecision::Float64},
}};

/// [output]: what to write beside the CSV/JSON files. Each key declared, defaulted and checked in
/// fields() (src/options/option_fields.hpp), which the scene reader walks.
struct OutputSpec {
  bool vtu = true;      ///< write solution.pvd + vtu/
  int vtu_stride = 1;   ///< write every k-th instant (the last one always), >= 1
  /// Float32 (ParaView renders in single precision; half the size of Float64 once compressed) or
  /// Float64. The exact numbers are in the CSV and JSON outputs.
  VtuPrecision vtu_precision = VtuPrecision::Float32;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("vtu", o.vtu, anyFlag());
    visit("vtu_stride", o.vtu_stride, atLeast(1));
    visit("vtu_precision", o.vtu_precision, Keywords<VtuPrecision>(kVtuPrecisions));
  }
};

}  // namespace stc
