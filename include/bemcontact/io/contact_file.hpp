#pragma once
// Two-body contact problem files (format in docs/contact.md): the file-level keys of a
// one-body file (title, analysis, interpolation, [parameters], [mesh]), two [[body]]
// tables each read by parse_body (plus `name` and an optional [body.interior] table of
// stress points), and a [contact] table:
//
//   [contact]
//   boundary1 = "contact"     # boundary of the first body that forms Gamma_c
//   boundary2 = "contact"     # boundary of the second body facing it
//   kind = "unilateral"       # or "bilateral"
//   friction = 0.1            # Coulomb beta (0: frictionless)
//   coupling = true           # false: drop the normal-tangential coupling (Spence E.1 check)
//   increments = 16           # quasi-static load steps
//   algorithm = "newton"      # or "thesis"
//   [contact.load]            # optional: a total force on a boundary (rigid platen)
//   body = "ball"
//   boundary = "top"
//   component = 2
//   force = -31.5
//
// Every error is an InputError naming the file, the line and the key. The contact zone is
// paired while reading, so boundaries that do not face each other, a zone that cannot be
// paired or bodies that overlap are reported against the [contact] table.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/parameter_overrides.hpp"
#include "bemcontact/contact/contact_problem.hpp"

namespace bemcontact::io {

struct ContactFile {
  contact::ContactProblem problem;
  std::map<std::string, double> parameters;
  std::vector<std::string> warnings;  // documented warnings of the reader (file:line: key ...)
  bool vtk = true;  // [output] vtk
};

// True when the file (TOML) holds a [contact] table: `bemcontact run` then reads it with
// read_contact_file and solves it with contact::solve_contact. False for unreadable files.
bool is_contact_file(const std::filesystem::path& path);
bool is_contact_text(std::string_view text);

ContactFile read_contact_file(const std::filesystem::path& path, const ParameterOverrides& overrides = {});
ContactFile parse_contact_problem(std::string_view text, const std::string& file_name,
                                  const ParameterOverrides& overrides = {},
    const ResourceLimits& limits = {});

}  // namespace bemcontact::io
