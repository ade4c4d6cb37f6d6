#pragma once
#include "bemcontact/validation/validation.hpp"

namespace bemcontact::validation {
std::vector<Record> run_plate_tension(const Context& context);
std::vector<Record> run_cantilever(const Context& context);
std::vector<Record> run_plate_hole(const Context& context);
std::vector<Record> run_thick_ring_plane_strain(const Context& context);
}  // namespace bemcontact::validation
