#pragma once
// The scheme of a case file (numerics.scheme) and the tables of its numerics: [numerics],
// [projection], [neighbours.<operator>] (docs/CASE_REFERENCE.md). Each reader refuses bad
// values (exit code 2, key named); the bounds of single keys are the schema's
// (case_schema.hpp).
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// numerics.scheme, then every key of the file that the schema gives to the other scheme is
// refused (numerics.delta_sph under "projection", [projection] under "wcsph"). First of the
// numerics: the scheme decides which keys apply.
void read_scheme(const Section& top, CaseConfig& c);
// [numerics] but the scheme: kernel, density, dissipation, time-step limits, skin.
void read_numerics(const Section& s, CaseConfig& c);
// [projection]: the pressure solve (read under the projection scheme only).
void read_projection(const Section& s, CaseConfig& c);
// Rules between the scheme and [walls]: the projection scheme needs wall particles, and
// numerics.wall_artificial_viscosity dummy walls. Needs the walls read.
void check_walls_for_scheme(const Section& top, const CaseConfig& c);
// [neighbours.gradient], [neighbours.laplacian], [neighbours.free_surface].
void read_neighbours(const Section& s, CaseConfig& c);

} // namespace sluice::case_file
