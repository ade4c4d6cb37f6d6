#pragma once
// The files of an elastoplastic run (docs/plasticity.md, Outputs), besides boundary.csv and
// boundary.vtk (the last step's boundary, stresses with the plastic strain):
//   cells.csv   cell,x,y,area,equivalent_plastic_strain,ep11,ep22,ep33,ep12,s11,s22,s12,s33,von_mises:
//               each cell's centroid, area, plastic state and stress at the last step's end
//               (after unloading: the residual stresses)
//   steps.csv   step,time,amplitude,newton_iterations,cuts,residual,held_cells,held_increment,yielded_cells,
//               max_equivalent_plastic_strain, then per boundary <name>_u1,<name>_u2 (the mean of
//               its nodes' displacements) and <name>_f1,<name>_f2 (its traction's resultant)
//   cells.vtk   the cells as polygons with cell data equivalent_plastic_strain, yielded (0/1)
//               and the stresses
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/io/output/csv_table.hpp"

namespace bemcontact::io {

CsvTable cells_table(const bem::ElastoplasticResult& result);
CsvTable elastoplastic_steps_table(const bem::ElastoplasticResult& result);
std::string cells_vtk(const bem::ElastoplasticResult& result, std::string_view title);

// The "elastoplastic" block of summary.json: cells (count, size range), steps, Newton
// iterations (total, largest per step), cuts, held cells, and the plastic zone (yielded
// cells, their area and the box around them, the largest equivalent plastic strain).
nlohmann::json elastoplastic_summary_json(const bem::ElastoplasticResult& result);

}  // namespace bemcontact::io
