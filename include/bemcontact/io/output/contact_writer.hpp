#pragma once
// Writers of a contact solution; each returns file contents, the command writes them
// (with OutputDirectory, all or nothing).
//
// One set of pair files per contact, named after it (<name>.csv, <name>_steps.csv,
// <name>_step<k>.csv; a single unnamed contact is "contact"):
//   contact.csv        one row per node pair (final state):
//                      pair,x,y,coordinate,nx,ny,gap,p_n,p_t,slip_ratio,jump_n,jump_t,status
//                      (x, y: body 1's node; n: common normal out of body 1; p_n < 0 in
//                      compression; slip_ratio = |p_t| / (beta |p_n|); jump = [u] = 1u - 2u;
//                      status open / stick / slip)
//   contact_steps.csv  one row per load step: step,time,a,c,stick_start,stick_end,stick_offset,
//                      contact_start,contact_end,peak_pressure,centre_pressure,normal_force,
//                      tangential_force,approach,pairs_in_contact,dissipated_energy,
//                      newton_iterations,kalker_iterations,threshold_iterations,gmres_cycles,residual
//                      (c: the stick zone's half-width, contact_summary.hpp)
//   motions.csv        one row per load step (when the problem has motions): step,time, then
//                      the columns of motion_columns
//   steps/contact_step<k>.csv  the pairs at step k (when record_steps; every per-step file
//                      is in the sub-folder steps/)
//   steps/<body>_boundary_step<k>.csv (when record_steps): every step's boundary fields
//   <body>_boundary.pvd, steps/<body>_boundary_step<k>.vtp (when record_steps and vtk):
//                      every step's boundary fields (u, t, stresses) as a ParaView time
//                      series (the .pvd names its files by their path, steps/...)
//   <body>_boundary.csv, <body>_interior.csv (+ .vtk): each elastic body's fields (each
//                      region's, named after it, in a body of several regions) (formats of
//                      io/results_writer.hpp), for stresses and von Mises iso-contours.
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/io/output/csv_table.hpp"
#include "bemcontact/io/output/run_summary.hpp"

namespace bemcontact::io {

// The CSV files as tables (io/output/csv_table.hpp; numbers written as CsvTable::compact),
// and as their text.
CsvTable contact_table(const std::vector<contact::PairResult>& pairs);
CsvTable contact_steps_table(const contact::ContactInterfaceResult& result);
std::string contact_csv(const std::vector<contact::PairResult>& pairs);
// The same pairs as VTK vertices (<contact>.vtk): point data p_n, p_t, gap, slip_ratio,
// jump_n, jump_t, status (0 open, 1 stick, 2 slip: field data status_names) and normal.
std::string contact_vtk(const std::vector<contact::PairResult>& pairs, std::string_view title);
// The same point data as VTK XML (<contact>_step<k>.vtp of the <contact>.pvd time series).
std::string contact_vtp(const std::vector<contact::PairResult>& pairs);
std::string contact_steps_csv(const contact::ContactInterfaceResult& result);

// The "contact" fragment of summary.json: kind, algorithm, friction, increments, unknowns,
// and the first contact's pairs, final a, c, c/a, peak and centre pressure, total normal
// force, approach delta, iterations per loop, residual, time per phase, and values per
// step. summary.json also holds "contacts": the same values per contact, with its name.
nlohmann::json contact_summary_json(const contact::ContactProblem& problem, const contact::ContactResult& result);

// A short text for the terminal: a, c, peak pressure, normal force, approach, iterations,
// and, for a force-loaded axisymmetric ball (an arc zone on body 1 facing a straight zone
// on body 2), the Hertz values a, p0, delta next to the computed ones (Annex D).
std::string contact_report_text(const contact::ContactProblem& problem, const contact::ContactResult& result);

// motions.csv's columns after step,time, named by body and direction: per force load the
// prescribed force and the approach (a force-displacement loop), <body>_<name>_force,
// <body>_<name>_displacement for a named load, <body>[_<boundary>]_<x|y>_force, ..._displacement
// otherwise (r, z in axisymmetry), _moment and _rotation for a moment; then each free
// body's rigid motion (ContactResult::free_motions): <body>_<x|y|z>_displacement, <body>_rotation.
// Characters other than letters and digits become '_'; a name met again gets _2, _3, ...
std::vector<std::string> motion_columns(const contact::ContactProblem& problem, const contact::ContactResult& result);

// Every file of a contact run (the CSV files as tables), summary.json left to the caller.
std::vector<OutputFile> contact_output_files(const contact::ContactProblem& problem,
                                             const contact::ContactResult& result, bool vtk = true);

// The blocks of summary.json a contact run (or bodies of regions) fills: kind, problem,
// options (law, solver, history, mesh), mesh, results (contact, contacts), reactions,
// timings (io/run_summary.hpp).
void fill_contact_summary(RunSummary& summary, const contact::ContactProblem& problem,
                          const contact::ContactResult& result);

// `bemcontact mesh` of a contact model (or of bodies of regions): per region
// <name>_mesh_nodes.csv, <name>_mesh_elements.csv, <name>_mesh.vtk, and per contact
// <name>_pairs.csv: pair,x1,y1,x2,y2,nx,ny,gap,weight (side 1's node, the point it faces,
// the pair normal, the initial gap d and the node's integration weight).
std::vector<OutputFile> contact_mesh_files(const contact::ContactProblem& problem,
                                           const contact::PreparedContact& prepared);

}  // namespace bemcontact::io
