#pragma once
// Output files of a decomposed solve, as (file name, content) pairs (nothing touches the
// disk: the command adds them to an OutputDirectory). Per subdomain <name>: the files of a
// one-body run prefixed by the name (<name>_boundary.csv, <name>_boundary.vtk,
// <name>_interior.csv, <name>_interior.vtk; io/results_writer.hpp), plus
//   interface.csv  interface,pair,kind,x,y,subdomain_a,node_a,subdomain_b,node_b,
//                  u1_a,u2_a,u1_b,u2_b,t1_a,t2_a,t1_b,t2_b,jump_u1,jump_u2,jump_t1,jump_t2
//                  (jump_u = u_a - u_b, jump_t = t_a + t_b: both vanish for a glued interface;
//                  kind is displacement for gamma_d pairs, traction for gamma_c)
//   interface.vtk  the pairs as vertices with point data jump_u, jump_t (vectors), kind
//   gmres.csv      iteration,relative_residual (the residual history of GMRES(m))
// and a JSON fragment for summary.json under the key "decomposition".
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bemcontact/dd/solver.hpp"
#include "bemcontact/io/output/csv_table.hpp"

namespace bemcontact::io {

// interface.csv and gmres.csv as tables (io/output/csv_table.hpp), and as their text.
CsvTable interface_table(const dd::DecompositionResult& result);
CsvTable gmres_history_table(const operators::GmresResult& gmres);
std::string interface_csv(const dd::DecompositionResult& result);
std::string interface_vtk(const dd::DecompositionResult& result, const std::string& title);
std::string gmres_history_csv(const operators::GmresResult& gmres);

// Every file of a decomposed run, in a fixed order (the CSV files as tables); VTK files
// only when `vtk`.
std::vector<OutputFile> decomposition_files(const dd::DecompositionResult& result, const std::string& title,
                                            bool vtk = true);

// {"method", "subdomains": [{name, nodes, elements, material, reciprocal_condition}],
//  "interfaces": [{name, subdomains, pairs, displacement_pairs, jump_u, jump_p}],
//  "interface_unknowns", "displacement_scale", "gmres": {restart, tolerance, status, message,
//  iterations, restarts, relative_residual}, "subdomain_solves", "factor_memory_bytes",
//  "timings": {phases, total}}
nlohmann::json decomposition_summary_json(const dd::DecompositionProblem& problem,
                                          const dd::DecompositionResult& result);

}  // namespace bemcontact::io
