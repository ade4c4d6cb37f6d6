#pragma once
// The definition of a one-body elasticity problem as the numerics see it: geometry,
// material, boundary conditions per piece, point constraints and interior points.
// Built by io/ from a problem file (or by code, e.g. the reference cases).
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/plasticity/j2_material.hpp"
#include "bemcontact/plasticity/region_cells.hpp"

namespace bemcontact::bem {

// A prescribed value as a function of the position (x, y), or (r, z) in axisymmetry.
using ScalarField = std::function<double(const Vec2& position)>;

enum class ConditionKind { displacement, traction };
// global: components along x and y (r and z); local: along the outward normal n and the
// tangent s = (-n_y, n_x), which points along the direction of travel.
enum class ConditionFrame { global, local };

struct BoundaryCondition {
  ConditionFrame frame = ConditionFrame::global;
  std::array<ConditionKind, 2> kind{ConditionKind::traction, ConditionKind::traction};
  std::array<ScalarField, 2> value;  // empty function = 0
  // Canonical text of the condition; pieces with equal signatures carry the same
  // condition, so the mesher need not split the node where they meet.
  std::string signature = "free";
  // Which amplitude of a load history scales the prescribed values (0: the body's data
  // amplitude; others: a boundary's own, contact model). Plain solves ignore it.
  int load_group = 0;

  double value_at(int component, const Vec2& position) const {
    return value[component] ? value[component](position) : 0.0;
  }
};

// Displacement prescribed at one point (e.g. u = 0 at a corner to remove rigid motion).
struct PointConstraint {
  Vec2 position = Vec2::Zero();
  std::array<std::optional<double>, 2> displacement;  // global components
  std::string label;   // vertex name or coordinates, for messages
  SourceLocation where;
};

// Dense matrices and LU, or hierarchical matrices and H-LU (bem/compressed_system.hpp).
enum class OperatorKind { automatic, dense, compressed };

// An elastoplastic region (docs/plasticity.md): the J2 material's yield stress and
// hardening ([material] yield_stress, hardening, kinematic_hardening) and the cells that
// cover where it may yield ([cells]).
struct RegionPlasticity {
  plasticity::J2Hardening hardening;
  plasticity::CellMeshOptions cells;
  SourceLocation where;        // the yield stress's key, for messages
  SourceLocation cells_where;  // the [cells] table
  // The boundary's elements given end points where the cells' vertices lie on it
  // (body_conforming_to_cells in bem/elastoplastic_analysis.hpp); false: the mesh as given.
  bool nodes_at_cells = true;
  // The cells' operator ([cells] operator): dense, or compressed (a hierarchical matrix of
  // their direct fields: bem/elastoplastic_region.hpp).
  OperatorKind cell_operator = OperatorKind::dense;
};

struct BodyDefinition {
  std::string name = "body";
  Material material;
  std::optional<RegionPlasticity> plasticity;  // none: linear elastic
  std::vector<geometry::BoundaryPiece> pieces;
  std::vector<BoundaryCondition> conditions;  // one per piece
  std::vector<PointConstraint> constraints;
};

struct InteriorPoint {
  Vec2 position;
  bool from_grid = false;  // grid points outside the body are dropped, listed ones are errors
  SourceLocation where;    // of a listed point in the problem file
  std::array<int, 2> grid_index = {-1, -1};  // column, row in its [interior] grid (-1: listed)
};

struct OperatorChoice {
  OperatorKind kind = OperatorKind::automatic;
  // Relative accuracy of the compressed blocks and of the H-LU; 0: automatic
  // (bem::compression_accuracy, compressed_system.hpp).
  double accuracy = 0.0;
  // `automatic` compresses plane problems from this many unknowns on (measured crossover:
  // docs/problem-file.md, Limits).
  static constexpr Index automatic_threshold = 8000;
};
const char* to_string(OperatorKind kind);


// What every problem starts with, whatever it holds (one body, a decomposition, bodies
// and contacts).
struct ProblemHeader {
  std::string title;
  std::string source_file;
  AnalysisType analysis = AnalysisType::plane_strain;
  geometry::MeshOptions mesh;           // interpolation, continuity, corner shift and transition
  OperatorChoice operator_choice;       // every region's boundary element system
};

struct ProblemDefinition : ProblemHeader {
  BodyDefinition body;
  std::vector<InteriorPoint> interior_points;
};

// Whether a body of `unknowns` unknowns is solved on compressed operators.
// `symmetry_lines`: the body's distinct symmetry lines (geometry/symmetry.hpp); with two,
// `auto` stays dense.
bool use_compressed_operator(const OperatorChoice& choice, Index unknowns, int symmetry_lines = 0);

}  // namespace bemcontact::bem
