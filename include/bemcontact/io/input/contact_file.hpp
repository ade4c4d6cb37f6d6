#pragma once
// Problem files of the model of bodies, regions and contacts (format in docs/contact.md):
// the file-level keys of a one-body file (title, analysis, interpolation, [parameters],
// [mesh], [output]); [[body]] tables, each with the one-body keys, [[body.region]] tables
// of them (bonded by interface = "...") or a [body.rigid] profile; contacts as
// [[contact]] tables with [solver] and [[load]], or, for two bodies, the thesis' single
// [contact] table holding all of them with [contact.load]; an optional [history]. A boundary
// may carry its own amplitude. Files with [[body]] tables and no contact are accepted too.
//
// Every error is an InputError naming the file, the line and the key. The contact zones
// are paired while reading, so boundaries that do not face each other, a zone that cannot
// be paired or bodies that overlap are reported against the contact tables.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"
#include "bemcontact/contact/contact_problem.hpp"

namespace bemcontact::io {

struct ContactFile {
  contact::ContactProblem problem;
  std::map<std::string, double> parameters;
  std::vector<std::string> warnings;  // documented warnings of the reader (file:line: key ...)
  bool vtk = true;  // [output] vtk
};


ContactFile read_contact_file(const std::filesystem::path& path, const ParameterOverrides& overrides = {});
ContactFile parse_contact_problem(std::string_view text, const std::string& file_name,
                                  const ParameterOverrides& overrides = {},
    const ResourceLimits& limits = {});

}  // namespace bemcontact::io
