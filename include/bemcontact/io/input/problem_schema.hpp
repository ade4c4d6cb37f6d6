#pragma once
// The keys of each table of a problem file (docs/problem-file.md describes them).
// One place, so that unknown-key messages can list the valid keys and point to the
// table where a misplaced key belongs.
#include <string>
#include <string_view>
#include <vector>

namespace bemcontact::io::schema {

const std::vector<std::string>& file_keys();        // file-level keys of the root table
const std::vector<std::string>& body_keys();        // body-level keys (root table for now)
const std::vector<std::string>& material_keys();    // [material]
const std::vector<std::string>& boundary_keys();    // [[boundary]]
const std::vector<std::string>& constraint_keys();  // [[constraint]]
const std::vector<std::string>& interior_keys();    // [interior]
const std::vector<std::string>& grid_keys();        // [interior] grid = {...}
const std::vector<std::string>& mesh_keys();        // [mesh]
const std::vector<std::string>& output_keys();      // [output]
const std::vector<std::string>& solver_keys();      // [solver] of a one-body file
const std::vector<std::string>& contact_law_keys();      // the law of a [[contact]] / [contact] table
const std::vector<std::string>& contact_pairing_keys();  // its pairing and gap keys
const std::vector<std::string>& tabulated_keys();   // t2 = { table = ..., along = ... }

// "the [material] table" when `key` is a key of another table than `section`, else "".
std::string section_of(std::string_view key, std::string_view section);

}  // namespace bemcontact::io::schema
