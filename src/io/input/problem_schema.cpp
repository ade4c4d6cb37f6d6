#include "bemcontact/io/input/problem_schema.hpp"

#include <algorithm>
#include <utility>

namespace bemcontact::io::schema {

const std::vector<std::string>& file_keys() {
  static const std::vector<std::string> keys{"title",    "analysis", "interpolation", "parameters",
                                             "interior", "mesh",     "output",       "solver"};
  return keys;
}
const std::vector<std::string>& solver_keys() {
  static const std::vector<std::string> keys{"operator", "accuracy"};
  return keys;
}
const std::vector<std::string>& contact_law_keys() {
  static const std::vector<std::string> keys{"kind", "friction", "coupling"};
  return keys;
}
const std::vector<std::string>& contact_pairing_keys() {
  static const std::vector<std::string> keys{"normal", "interference", "interference_amplitude", "gap"};
  return keys;
}
const std::vector<std::string>& body_keys() {
  static const std::vector<std::string> keys{"material", "vertices", "boundary", "constraint", "geometry"};
  return keys;
}
const std::vector<std::string>& material_keys() {
  static const std::vector<std::string> keys{"E", "nu"};
  return keys;
}
const std::vector<std::string>& boundary_keys() {
  static const std::vector<std::string> keys{
      "name", "shape", "from", "to", "center", "direction", "elements", "grading", "refine",
      "u1",   "u2",    "t1",   "t2", "un",     "ut",        "tn",       "tt",      "pressure", "symmetry"};
  return keys;
}
const std::vector<std::string>& constraint_keys() {
  static const std::vector<std::string> keys{"at", "u1", "u2"};
  return keys;
}
const std::vector<std::string>& interior_keys() {
  static const std::vector<std::string> keys{"points", "grid"};
  return keys;
}
const std::vector<std::string>& grid_keys() {
  static const std::vector<std::string> keys{"x", "y", "r", "z"};
  return keys;
}
const std::vector<std::string>& mesh_keys() {
  static const std::vector<std::string> keys{"corner_shift", "corner_transition", "continuity"};
  return keys;
}
const std::vector<std::string>& output_keys() {
  static const std::vector<std::string> keys{"vtk"};
  return keys;
}
const std::vector<std::string>& tabulated_keys() {
  static const std::vector<std::string> keys{"table", "along"};
  return keys;
}

std::string section_of(std::string_view key, std::string_view section) {
  // Sections a user could plausibly confuse; the root table comes first.
  const std::pair<const char*, const std::vector<std::string>*> sections[] = {
      {"the top level of the file", &file_keys()},
      {"the top level of the file", &body_keys()},
      {"the [material] table", &material_keys()},
      {"each [[boundary]] table", &boundary_keys()},
      {"each [[constraint]] table", &constraint_keys()},
      {"the [interior] table", &interior_keys()},
      {"the [mesh] table", &mesh_keys()},
      {"the [output] table", &output_keys()},
      {"the [solver] table", &solver_keys()},
      {"each [[contact]] table (the law of that contact; or the single [contact] table)", &contact_law_keys()},
  };
  for (const auto& [name, keys] : sections) {
    if (section == name) continue;
    if (std::find(keys->begin(), keys->end(), key) != keys->end()) return name;
  }
  return {};
}

}  // namespace bemcontact::io::schema
