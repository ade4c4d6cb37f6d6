#include "bemcontact/io/output/plasticity_writer.hpp"

#include <algorithm>
#include <limits>

#include "bemcontact/io/file_names.hpp"
#include "bemcontact/io/output/results_writer.hpp"

namespace bemcontact::io {

namespace {

bem::StressTensor stress_tensor(const plasticity::Mandel& s) {
  return bem::StressTensor{s[0], s[1], plasticity::component12(s), s[2]};
}

}  // namespace

CsvTable cells_table(const bem::ElastoplasticResult& result) {
  const auto c = CsvTable::compact;
  CsvTable table({{"cell", CsvTable::integer}, {"x", c}, {"y", c}, {"area", c}, {"equivalent_plastic_strain", c},
                  {"ep11", c}, {"ep22", c}, {"ep33", c}, {"ep12", c}, {"s11", c}, {"s22", c}, {"s12", c},
                  {"s33", c}, {"von_mises", c}});
  table.reserve(result.cells.size());
  for (std::size_t k = 0; k < result.cells.size(); ++k) {
    const Vec2 centroid = result.cells[k].centroid();
    const auto& state = result.states[k];
    const auto& ep = state.plastic_strain;
    const bem::StressTensor s = stress_tensor(result.cell_stress[k]);
    table.row() << static_cast<double>(k) << centroid.x() << centroid.y() << result.cells[k].area()
                << state.equivalent_plastic_strain << ep[0] << ep[1] << ep[2] << plasticity::component12(ep) << s.s11
                << s.s22 << s.s12 << s.s33 << s.von_mises();
  }
  return table;
}

CsvTable elastoplastic_steps_table(const bem::ElastoplasticResult& result) {
  const auto c = CsvTable::compact, i = CsvTable::integer;
  CsvTable table({{"step", i}, {"time", c}, {"amplitude", c}, {"newton_iterations", i}, {"cuts", i},
                  {"residual", c}, {"held_cells", i}, {"held_increment", c}, {"yielded_cells", i}, {"max_equivalent_plastic_strain", c}});
  const auto& names = result.mesh.piece_names;
  for (const auto& name : names)
    for (const char* column : {"_u1", "_u2", "_f1", "_f2"}) table.add_column(file_stem(name) + column, c);
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    const auto& step = result.steps[k];
    auto row = table.row();
    row << static_cast<double>(k + 1) << step.time << step.amplitude << step.report.newton_iterations
        << step.report.cuts << step.report.residual << step.report.held_cells << step.report.held_increment
        << step.yielded_cells
        << step.max_equivalent_plastic_strain;
    for (std::size_t p = 0; p < names.size(); ++p) {
      const Vec2 u = p < step.mean_displacement.size() ? step.mean_displacement[p] : Vec2::Zero();
      Vec2 f = Vec2::Zero();
      for (const auto& r : step.resultants)
        if (r.boundary == names[p]) f = r.force;
      row << u.x() << u.y() << f.x() << f.y();
    }
  }
  return table;
}

std::string cells_vtk(const bem::ElastoplasticResult& result, std::string_view title) {
  std::vector<std::vector<Vec2>> polygons;
  std::vector<double> kappa, yielded;
  std::vector<bem::StressTensor> stress;
  for (std::size_t k = 0; k < result.cells.size(); ++k) {
    polygons.push_back(result.cells[k].vertices);
    kappa.push_back(result.states[k].equivalent_plastic_strain);
    yielded.push_back(kappa.back() > 0.0 ? 1.0 : 0.0);
    stress.push_back(stress_tensor(result.cell_stress[k]));
  }
  return polygons_vtk(title, polygons, {{"equivalent_plastic_strain", kappa}, {"yielded", yielded}}, stress);
}

nlohmann::json elastoplastic_summary_json(const bem::ElastoplasticResult& result) {
  const auto sizes = plasticity::cell_size_range(result.cells);
  int iterations = 0, most_iterations = 0, cuts = 0, held = 0;
  for (const auto& step : result.steps) {
    iterations += step.report.newton_iterations;
    most_iterations = std::max(most_iterations, step.report.newton_iterations);
    cuts += step.report.cuts;
    held = std::max(held, step.report.held_cells);
  }
  int yielded = 0;
  double area = 0.0, max_kappa = 0.0;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t k = 0; k < result.cells.size(); ++k) {
    const double kappa = result.states[k].equivalent_plastic_strain;
    max_kappa = std::max(max_kappa, kappa);
    if (!(kappa > 0.0)) continue;
    ++yielded;
    area += result.cells[k].area();
    for (const Vec2& v : result.cells[k].vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  }
  nlohmann::json zone = {{"yielded_cells", yielded}, {"area", area}, {"max_equivalent_plastic_strain", max_kappa}};
  if (yielded > 0) zone["box"] = {{lo.x(), lo.y()}, {hi.x(), hi.y()}};
  return {{"cells", result.cells.size()},
          {"largest_cell", sizes[0]},
          {"smallest_cell", sizes[1]},
          {"steps", result.steps.size()},
          {"newton_iterations", iterations},
          {"most_newton_iterations_in_a_step", most_iterations},
          {"cuts", cuts},
          {"most_held_cells", held},
          {"plastic_zone", zone}};
}

}  // namespace bemcontact::io
