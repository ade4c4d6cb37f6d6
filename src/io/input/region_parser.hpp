#pragma once
// The readers' own parser of one region table (private: its signature is toml++'s).
#include <string>

#include <toml++/toml.h>

#include "bemcontact/dd/decomposition.hpp"
#include "io/input/toml_reader.hpp"

namespace bemcontact::io {

// One region (subdomain) table: the body-level keys of a one-body file, name and interior
// handled by the caller; `table_keys` is its table in the schema ("subdomain", "body",
// "region") and `boundary_keys` its boundaries' ("region.boundary", "body.boundary"). A
// boundary with interface = "<name>" is a bond (no condition). Vertices of
// shared_vertices not defined in the table are added to it.
dd::Subdomain parse_region(toml::table& table, const std::string& path, FileContext& context, int line,
                           const std::string& name, const schema::Table& table_keys,
                           const schema::Table& boundary_table, const toml::table* shared_vertices = nullptr);

}  // namespace bemcontact::io
