#pragma once
// The files of `stcontact svd` (docs/svd_seed.md), as strings for writeFileAtomically: the seed's
// Fig. 3a data (singular values and cumulative energy), Fig. 3b (time functions ν_i √σ_i), Fig. 2
// (spatial modes Υ_i √σ_i, as a ParaView file and as gnuplot polygons) and the localisation table.
// Scaling by √σ_i follows the seed's figure captions: σ_i Υ_i ν_iᵀ = (√σ_i Υ_i)(√σ_i ν_i)ᵀ.
#include <string>
#include <vector>

#include "stcontact/mesh/tri_mesh.hpp"
#include "stcontact/pgd/space_time_svd.hpp"
#include "stcontact/studies/mode_localisation.hpp"

namespace stc {

/// i,sigma,energy_fraction,cumulative_energy — one row per computed pair, i from 1; the fractions
/// are of the whole ‖U‖²_K, so they stay exact when only the leading pairs were computed.
std::string singularValuesCsv(const pgd::SpaceTimeSvd& svd);

/// t,mode_1,…,mode_N — ν_i(t_k) √σ_i for the first N pairs.
std::string timeFunctionsCsv(const pgd::SpaceTimeSvd& svd, const std::vector<double>& times, int modes);

/// mode,sigma,energy_fraction,resolved,share_d<d>… (one column per band depth),concentration_d<d>…,
/// mean_distance — LocalisationMeasure of Υ_i for the first N pairs (header: mode_localisation.hpp).
/// A mode below the resolution floor (resolved = 0, Υ_i = 0) gets empty measure cells.
std::string localisationCsv(const pgd::SpaceTimeSvd& svd, const ModeLocalisation& localisation, int modes);

/// modes.vtu: point fields mode_1…mode_N (Υ_i √σ_i, 2 × nodes) and, when `localisation` is given,
/// cell fields energy_density_1… (E_e / A_e of Υ_i, energy per unit area of the unit-energy mode).
std::string modesVtu(const TriMesh& mesh, const pgd::SpaceTimeSvd& svd, int modes, const ModeLocalisation* localisation);

/// Gnuplot data for the deformed-mode figure: for each of the first N pairs one data block
/// (blocks separated by two blank lines, gnuplot's `index`), each triangle of the deformed mesh
/// x + s_i Υ_i √σ_i as four lines "x y c" (the first vertex repeated) and a blank line; c is the element's energy density
/// relative to the mode's mean density (E_e/A_e)/(Σ E_e/Σ A_e), or 1 without `localisation`.
/// s_i makes the largest nodal displacement `max_displacement` (e.g. 0.12 R); returned in `scales`.
std::string deformedModesData(const TriMesh& mesh, const pgd::SpaceTimeSvd& svd, int modes,
                              const ModeLocalisation* localisation, double max_displacement,
                              std::vector<double>& scales);

}  // namespace stc
