#include "bemcontact/io/output/decomposition_writer.hpp"

#include "bemcontact/io/file_names.hpp"

#include <sstream>

#include "bemcontact/io/output/json_writer.hpp"
#include "bemcontact/io/output/results_writer.hpp"
#include "bemcontact/io/text_format.hpp"

namespace bemcontact::io {

namespace {

const char* kind_name(bem::ConditionKind kind) {
  return kind == bem::ConditionKind::displacement ? "displacement" : "traction";
}

}  // namespace

CsvTable interface_table(const dd::DecompositionResult& result) {
  constexpr auto text = CsvTable::text;
  constexpr auto integer = CsvTable::integer;
  CsvTable table({{"interface", text}, {"pair", integer}, {"kind", text}, {"x"}, {"y"}, {"subdomain_a", text},
                  {"node_a", integer}, {"subdomain_b", text}, {"node_b", integer}, {"u1_a"}, {"u2_a"}, {"u1_b"},
                  {"u2_b"}, {"t1_a"}, {"t2_a"}, {"t1_b"}, {"t2_b"}, {"jump_u1"}, {"jump_u2"}, {"jump_t1"},
                  {"jump_t2"}});
  for (const auto& interface : result.connectivity.interfaces) {
    const auto& a = result.subdomains[interface.subdomain_a];
    const auto& b = result.subdomains[interface.subdomain_b];
    for (std::size_t j = 0; j < interface.pairs.size(); ++j) {
      const auto& pair = interface.pairs[j];
      const Vec2 ua = a.boundary.displacement[pair.node_a], ub = b.boundary.displacement[pair.node_b];
      const Vec2 ta = a.boundary.traction[pair.node_a], tb = b.boundary.traction[pair.node_b];
      const Vec2 ju = ua - ub, jt = ta + tb;
      auto row = table.row();
      row << interface.name << static_cast<double>(j) << kind_name(pair.kind) << pair.position.x()
          << pair.position.y() << a.name << static_cast<double>(pair.node_a) << b.name
          << static_cast<double>(pair.node_b);
      for (const Vec2* v : {&ua, &ub, &ta, &tb, &ju, &jt}) row << v->x() << v->y();
    }
  }
  return table;
}

std::string interface_csv(const dd::DecompositionResult& result) { return csv_text(interface_table(result)); }

std::string interface_vtk(const dd::DecompositionResult& result, const std::string& title) {
  std::vector<const dd::NodePair*> pairs;
  std::vector<Vec2> jump_u, jump_t;
  for (const auto& interface : result.connectivity.interfaces) {
    const auto& a = result.subdomains[interface.subdomain_a].boundary;
    const auto& b = result.subdomains[interface.subdomain_b].boundary;
    for (const auto& pair : interface.pairs) {
      pairs.push_back(&pair);
      jump_u.push_back(a.displacement[pair.node_a] - b.displacement[pair.node_b]);
      jump_t.push_back(a.traction[pair.node_a] + b.traction[pair.node_b]);
    }
  }
  const std::size_t n = pairs.size();
  std::ostringstream out;
  std::string safe_title = title;
  for (char& c : safe_title)
    if (c == '\n' || c == '\r') c = ' ';
  out << "# vtk DataFile Version 3.0\n" << safe_title.substr(0, 255) << " (interfaces)\nASCII\nDATASET POLYDATA\n";
  out << "POINTS " << n << " double\n";
  for (const auto* pair : pairs)
    out << format_number(pair->position.x()) << ' ' << format_number(pair->position.y()) << " 0\n";
  out << "VERTICES " << n << ' ' << 2 * n << '\n';
  for (std::size_t k = 0; k < n; ++k) out << "1 " << k << '\n';
  out << "POINT_DATA " << n << '\n';
  for (const auto& [name, values] : {std::pair{"jump_u", &jump_u}, std::pair{"jump_t", &jump_t}}) {
    out << "VECTORS " << name << " double\n";
    for (const Vec2& v : *values) out << format_number(v.x()) << ' ' << format_number(v.y()) << " 0\n";
  }
  out << "SCALARS displacement_continuity int 1\nLOOKUP_TABLE default\n";
  for (const auto* pair : pairs) out << (pair->kind == bem::ConditionKind::displacement ? 1 : 0) << '\n';
  return out.str();
}

CsvTable gmres_history_table(const operators::GmresResult& gmres) {
  CsvTable table({{"iteration", CsvTable::integer}, {"relative_residual"}});
  table.reserve(gmres.residual_history.size());
  for (std::size_t k = 0; k < gmres.residual_history.size(); ++k)
    table.row() << static_cast<double>(k) << gmres.residual_history[k];
  return table;
}

std::string gmres_history_csv(const operators::GmresResult& gmres) { return csv_text(gmres_history_table(gmres)); }

std::vector<OutputFile> decomposition_files(const dd::DecompositionResult& result, const std::string& title,
                                            bool vtk) {
  std::vector<OutputFile> files;
  const auto add = [&](std::string name, auto content) { files.push_back({std::move(name), std::move(content)}); };
  for (const auto& sub : result.subdomains) {
    const std::string prefix = file_stem(sub.name) + "_";
    add(prefix + "boundary.csv", boundary_table(sub.mesh, sub.boundary));
    if (vtk) add(prefix + "boundary.vtk", boundary_vtk(sub.mesh, sub.boundary, title + " / " + sub.name));
    if (!sub.interior.points.empty()) {
      add(prefix + "interior.csv", interior_table(sub.interior));
      if (vtk) add(prefix + "interior.vtk", interior_vtk(sub.interior, title + " / " + sub.name));
    }
  }
  add("interface.csv", interface_table(result));
  if (vtk) add("interface.vtk", interface_vtk(result, title));
  add("gmres.csv", gmres_history_table(result.gmres));
  return files;
}

nlohmann::json decomposition_summary_json(const dd::DecompositionProblem& problem,
                                          const dd::DecompositionResult& result) {
  nlohmann::json j;
  j["method"] = dd::to_string(result.method);
  j["preconditioner"] = dd::to_string(result.preconditioner);
  if (result.preconditioner == dd::InterfacePreconditioner::balancing) {
    j["coarse_dimension"] = result.coarse_dimension;
    j["floating_modes"] = result.floating_modes;
  }
  nlohmann::json subs = nlohmann::json::array();
  for (std::size_t s = 0; s < result.subdomains.size(); ++s) {
    const auto& sub = result.subdomains[s];
    const auto& material = problem.subdomains[s].body.material;
    subs.push_back({{"name", sub.name},
                    {"nodes", sub.mesh.node_count()},
                    {"elements", sub.mesh.element_count()},
                    {"graded_toward_vertices", mesh_transitions_json(sub.mesh)},
                    {"boundary_resultants", resultants_json(sub.boundary.resultants, problem.analysis)},
                    {"material", {{"E", material.young_modulus}, {"nu", material.poisson_ratio}}},
                    {"reciprocal_condition", condition_json(sub.reciprocal_condition)},
                    {"process", s < result.owner.size() ? result.owner[s] : 0}});
  }
  j["subdomains"] = subs;
  nlohmann::json interfaces = nlohmann::json::array();
  for (std::size_t i = 0; i < result.connectivity.interfaces.size(); ++i) {
    const auto& interface = result.connectivity.interfaces[i];
    const auto& jump = result.jumps[i];
    interfaces.push_back({{"name", interface.name},
                          {"subdomains", {result.subdomains[interface.subdomain_a].name,
                                          result.subdomains[interface.subdomain_b].name}},
                          {"pairs", jump.pairs},
                          {"displacement_pairs", jump.displacement_pairs},
                          {"jump_u", jump.jump_u},
                          {"jump_p", jump.jump_p}});
  }
  j["interfaces"] = interfaces;
  j["interface_unknowns"] = result.interface_unknowns;
  j["displacement_scale"] = result.displacement_scale;
  j["gmres"] = {{"restart", dd::effective_restart(problem.options, result.interface_unknowns)},
                {"tolerance", problem.options.tolerance},
                {"max_iterations", problem.options.max_iterations},
                {"status", operators::to_string(result.gmres.status)},
                {"message", result.gmres.message},
                {"iterations", result.gmres.iterations},
                {"restarts", result.gmres.restarts},
                {"relative_residual", result.gmres.relative_residual}};
  if (problem.options.method == dd::InterfaceMethod::mixed)
    j["displacement_nodes"] = problem.options.displacement_nodes;
  j["explicit_operators"] = problem.options.explicit_operators;
  j["subdomain_solves"] = result.subdomain_solves;
  j["processes"] = result.processes;
  j["factor_memory_bytes"] = result.factor_memory_bytes;
  j["timings"] = timings_json(result.timings);
  return j;
}

}  // namespace bemcontact::io
