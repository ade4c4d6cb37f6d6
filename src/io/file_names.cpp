#include "bemcontact/io/file_names.hpp"

#include <cctype>

namespace bemcontact::io {

std::string file_stem(const std::string& name) {
  std::string out;
  for (const char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return out;
}

std::string body_file_prefix(const std::string& name, bool named) { return named ? file_stem(name) + "_" : ""; }

std::vector<std::string> contact_file_names(const std::string& contact) {
  const std::string stem = file_stem(contact);
  return {stem + ".csv", stem + ".vtk", stem + "_steps.csv", stem + ".pvd", stem + "_pairs.csv"};
}

std::vector<std::string> region_file_names(const std::string& region) {
  const std::string stem = file_stem(region);
  return {stem + "_boundary.csv", stem + "_boundary.vtk", stem + "_boundary.pvd",    stem + "_interior.csv",
          stem + "_interior.vtk", stem + "_mesh_nodes.csv", stem + "_mesh_elements.csv", stem + "_mesh.vtk"};
}

std::vector<std::string> model_file_names() { return {"motions.csv", "summary.json"}; }

}  // namespace bemcontact::io
