#include "bemcontact/bem/elastoplastic_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <sstream>
#include <unordered_map>

#include "bemcontact/bem/assembly.hpp"
#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/integration/axisymmetric_element.hpp"
#include "bemcontact/integration/plane_element.hpp"
#include "bemcontact/plasticity/ring_initial_stress.hpp"
#include "bemcontact/operators/dense_lu.hpp"
#include "bemcontact/operators/row_partitioned_hmatrix.hpp"

namespace bemcontact::bem {

using plasticity::Cell;
using plasticity::component12;
using plasticity::J2Hardening;
using plasticity::j2_update;
using plasticity::mandel;
using plasticity::in_plane_stiffness;
using plasticity::J2State;
using plasticity::J2Update;
using plasticity::Mandel;
using plasticity::Matrix33;

namespace {

const double kSqrt2 = std::sqrt(2.0);


// The cells' kernels and components: plane (11, 22, 12) or axisymmetric (rr, zz, rz, tt),
// the tensor components of a cell's strain, stress and initial stress.
struct CellKernels {
  AnalysisType type;
  Material material;
  kernels::KelvinPlane plane;
  kernels::KelvinAxisymmetric ring;
  integration::AxisymmetricKelvin axi;
  int d = 3;

  CellKernels(AnalysisType t, const Material& m)
      : type(t), material(m),
        plane(kernels::KelvinPlane::from(t == AnalysisType::axisymmetric ? AnalysisType::plane_strain : t, m)),
        ring{m.shear_modulus(), m.poisson_ratio}, axi(integration::AxisymmetricKelvin::from(m)),
        d(t == AnalysisType::axisymmetric ? 4 : 3) {}
  bool axisymmetric() const { return d == 4; }

  // The displacement at x per unit initial stress component of the cell (2 x d).
  Matrix displacement(const Vec2& x, const Cell& cell) const {
    if (axisymmetric()) return plasticity::ring_cell_displacement_influence(ring, x, cell);
    return plasticity::cell_displacement_influence(plane, x, cell);
  }
  // C eps at x per unit initial stress component of the cell (d x d).
  Matrix stress(const Vec2& x, const Cell& cell) const {
    if (axisymmetric()) return plasticity::ring_cell_stress_influence(ring, x, cell);
    return plasticity::cell_stress_influence(plane, x, cell);
  }
  // C on the components: plane strain's or plane stress's in-plane one, or the 3D one on
  // (rr, zz, rz, tt).
  Matrix stiffness() const {
    if (!axisymmetric()) return plasticity::in_plane_stiffness(type, material);
    const double G = material.shear_modulus(), nu = material.poisson_ratio;
    const double lambda = 2.0 * G * nu / (1.0 - 2.0 * nu);
    Matrix C = Matrix::Zero(4, 4);
    for (const int i : {0, 1, 3})
      for (const int j : {0, 1, 3}) C(i, j) = lambda + (i == j ? 2.0 * G : 0.0);
    C(2, 2) = 2.0 * G;
    return C;
  }
  // The Mandel vector (11, 22, 33, sqrt2 12) of a cell's strain (plane: eps_33 given).
  Mandel strain_of(const Vector& E, double eps33 = 0.0) const {
    return axisymmetric() ? mandel(E[0], E[1], E[3], E[2]) : mandel(E[0], E[1], eps33, E[2]);
  }
  // The Mandel row of each component (its third, 12 or rz, is sqrt2 times the tensor's).
  std::vector<int> mandel_rows() const {
    return axisymmetric() ? std::vector<int>{0, 1, 3, 2} : std::vector<int>{0, 1, 3};
  }
};

// The conditions with their prescribed values times `scale`.
std::vector<NodeCondition> scaled(std::vector<NodeCondition> conditions, double scale) {
  for (auto& c : conditions) c.value = {scale * c.value[0], scale * c.value[1]};
  return conditions;
}

// The conditions with their prescribed values times their load group's amplitude.
std::vector<NodeCondition> scaled(std::vector<NodeCondition> conditions, const Vector& amplitudes) {
  for (auto& c : conditions) {
    const double a = amplitudes[c.load_group];
    c.value = {a * c.value[0], a * c.value[1]};
  }
  return conditions;
}

// Nodal values (u, t), 4N, of the boundary unknowns y.
Vector boundary_values(const Vector& y, const std::vector<NodeCondition>& conditions,
                       const std::vector<ConstraintEquation>& constraints) {
  const BoundarySolution s = recover_boundary_values(y, conditions, constraints);
  const Index n = static_cast<Index>(s.displacement.size());
  Vector out(4 * n);
  for (Index i = 0; i < n; ++i) {
    out.segment<2>(2 * i) = s.displacement[static_cast<std::size_t>(i)];
    out.segment<2>(2 * n + 2 * i) = s.traction[static_cast<std::size_t>(i)];
  }
  return out;
}

using MeanPoints = std::vector<std::pair<Vec2, double>>;

// Each cell's mean points: twice as fine each way within 2 cell sizes of the boundary (the
// centroids of cells on a grid aligned with it lie at half sizes: none on the threshold),
// where Somigliana's stress varies on the elements' scale (a cell at a loaded edge: its
// mean off by 1.3 % with the coarse rule, 0.25 % with the fine one, against 16 x 16).
std::vector<MeanPoints> cell_mean_points(const geometry::BoundaryMesh& mesh, const std::vector<Cell>& cells) {
  std::vector<MeanPoints> out;
  for (const auto& cell : cells) {
    const Vec2 centroid = cell.centroid();
    double distance = std::numeric_limits<double>::infinity();
    for (const auto& element : mesh.elements) {
      const double f = std::clamp((centroid - element.start).dot(element.tangent) / element.length, 0.0, 1.0);
      distance = std::min(distance, (centroid - (element.start + f * (element.end - element.start))).norm());
    }
    out.push_back(cell.mean_points(distance < 2.0 * std::sqrt(std::abs(cell.area())) ? 2 : 1));
  }
  return out;
}

// Somigliana's C E averaged over each cell (its mean points) as a map of the nodal (u, t):
// sigma = int D t - int S u (I.14), the elements' images across symmetry lines included
// (their nodal values S times the element's); d rows per cell (11, 22, 12, and tt in
// axisymmetry). Each cell's rows by one thread: deterministic for any thread count.
Matrix mean_somigliana_rows(const geometry::BoundaryMesh& mesh, const CellKernels& kernels,
                            const std::vector<MeanPoints>& means) {
  const Index n = mesh.node_count(), m = static_cast<Index>(means.size()), d = kernels.d;
  Matrix rows = Matrix::Zero(d * m, 4 * n);
  const auto add = [&](Index c, double weight, const geometry::BoundaryElement& element, const Mat2& S,
                       const Vec2& x) {
    integration::ElementStressInfluence s;
    integration::AxisymmetricStressInfluence ring;
    if (kernels.axisymmetric()) {
      ring = integration::integrate_axisymmetric_element_stress(kernels.axi, x, element);
      s = ring.in_plane;
    } else {
      s = integration::integrate_plane_element_stress(kernels.plane, x, element);
    }
    for (int a = 0; a < element.node_count; ++a)
      for (int l = 0; l < 2; ++l) {  // the node's own component l, S(k, l) of it in the image's component k
        Mat2 D = Mat2::Zero(), Sk = Mat2::Zero();
        double hoop_D = 0.0, hoop_S = 0.0;
        for (int k = 0; k < 2; ++k) {
          D += S(k, l) * s.D[a][k], Sk += S(k, l) * s.S[a][k];
          hoop_D += S(k, l) * ring.hoop_D[a][k], hoop_S += S(k, l) * ring.hoop_S[a][k];
        }
        const Index u = 2 * element.nodes[a] + l, t = 2 * n + u;
        rows(d * c, t) += weight * D(0, 0), rows(d * c + 1, t) += weight * D(1, 1);
        rows(d * c + 2, t) += weight * 0.5 * (D(0, 1) + D(1, 0));
        rows(d * c, u) -= weight * Sk(0, 0), rows(d * c + 1, u) -= weight * Sk(1, 1);
        rows(d * c + 2, u) -= weight * 0.5 * (Sk(0, 1) + Sk(1, 0));
        if (kernels.axisymmetric()) rows(d * c + 3, t) += weight * hoop_D, rows(d * c + 3, u) -= weight * hoop_S;
      }
  };
#pragma omp parallel for schedule(dynamic, 1)
  for (Index c = 0; c < m; ++c)
    for (const auto& [x, weight] : means[static_cast<std::size_t>(c)])
      for (const auto& element : mesh.elements) {
        add(c, weight, element, Mat2::Identity(), x);
        for (const auto& image : mesh.images) add(c, weight, geometry::image_element(element, image), image.matrix, x);
      }
  return rows;
}

}  // namespace

// A cell and its images across the symmetry lines, each with the map of the cell's initial
// stress components to its own: sigma0' = S sigma0 S^T (the hoop component unchanged).
// (Outside the anonymous namespace: PlasticCellFields keeps them.)
struct CellImage {
  Cell cell;
  Matrix stress_map;
};

namespace {
std::vector<CellImage> cell_and_images(const Cell& cell, const std::vector<geometry::ImageMap>& images, int d) {
  std::vector<CellImage> out{{cell, Matrix::Identity(d, d)}};
  for (const auto& image : images) {
    CellImage mirrored{{}, Matrix::Identity(d, d)};
    for (const Vec2& v : cell.vertices) mirrored.cell.vertices.push_back(image.apply(v));
    if (image.reverses()) std::reverse(mirrored.cell.vertices.begin(), mirrored.cell.vertices.end());
    const Mat2& S = image.matrix;
    for (int j = 0; j < 3; ++j) {
      Mat2 unit = Mat2::Zero();
      if (j < 2) unit(j, j) = 1.0;
      else unit(0, 1) = unit(1, 0) = 1.0;
      const Mat2 mapped = S * unit * S.transpose();
      mirrored.stress_map.block(0, j, 3, 1) = Eigen::Vector3d(mapped(0, 0), mapped(1, 1), mapped(0, 1));
    }
    out.push_back(std::move(mirrored));
  }
  return out;
}

}  // namespace

// The direct field of one cell (and its images) averaged over another: C E over cell c per
// unit initial stress of cell e (d x d), K's part besides the boundary's (R V). For the dense
// operator a cell far from cell e (centroids more than kFarCells sizes apart) takes the field
// at its centroid for its mean: the difference is of order (size / distance)^2 of a small
// term. The compressed operator (`smooth`) takes the mean everywhere: that switch is a jump
// of about 1e-3 of the far blocks, which kept their ranks high (compression ratio 0.86 at
// 1 039 cells against 0.49 without it). Pure: called from several threads at once.
class CellFieldBlocks {
 public:
  CellFieldBlocks(const CellKernels& kernels, const std::vector<Cell>& cells, std::vector<MeanPoints> means,
                  const std::vector<geometry::ImageMap>& images, bool smooth)
      : kernels_(kernels), means_(std::move(means)), smooth_(smooth) {
    for (const auto& cell : cells) {
      sources_.push_back(cell_and_images(cell, images, kernels.d));
      centroid_.push_back(cell.centroid());
      size_.push_back(std::sqrt(std::abs(cell.area())));
    }
  }
  Matrix block(std::size_t c, std::size_t e) const {
    constexpr double kFarCells = 6.25;  // not a lattice distance of equal cells (12.5 sizes): no tie on a grid
    Matrix out = Matrix::Zero(kernels_.d, kernels_.d);
    for (const auto& source : sources_[e]) {
      if (!smooth_ && (source.cell.centroid() - centroid_[c]).norm() > kFarCells * (size_[c] + size_[e])) {
        out += kernels_.stress(centroid_[c], source.cell) * source.stress_map;
        continue;
      }
      for (const auto& [x, weight] : means_[c]) out += weight * kernels_.stress(x, source.cell) * source.stress_map;
    }
    return out;
  }
  const std::vector<Vec2>& centroids() const { return centroid_; }

 private:
  CellKernels kernels_;
  std::vector<MeanPoints> means_;
  bool smooth_;
  std::vector<std::vector<CellImage>> sources_;
  std::vector<Vec2> centroid_;
  std::vector<double> size_;
};

// The cells' direct fields: their blocks, and with the compressed cell operator
// ([cells] operator = "compressed") D as a hierarchical matrix over all cells, for the
// products K x = R (V x) + D x, and K's block on the cells that have yielded (`kept`, grown
// as cells first yield: O(p^2), where the dense operator keeps their whole columns, O(m p)),
// for the Newton system.
struct ElastoplasticRegion::DirectFields {
  explicit DirectFields(CellFieldBlocks b) : blocks(std::move(b)) {}
  CellFieldBlocks blocks;
  std::unique_ptr<operators::RowPartitionedHMatrix> compressed;
  std::vector<Index> kept;      // cells of the kept block, in the order they joined
  std::vector<Index> position;  // each cell's place in `kept` (-1: not there)
  Matrix block;                 // K on the kept cells' components
};

namespace {

// Adds the direct fields of the cells `columns` to their columns of K. Each row block by
// one thread: deterministic for any thread count.
void add_cell_fields(const CellFieldBlocks& blocks, Index d, const std::vector<Index>& columns, std::vector<Matrix>& K) {
  const std::size_t m = blocks.centroids().size();
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t c = 0; c < m; ++c)
    for (const Index e : columns)
      K[static_cast<std::size_t>(e)].middleRows(d * static_cast<Index>(c), d) += blocks.block(c, static_cast<std::size_t>(e));
}

}  // namespace

ElastoplasticRegion::ElastoplasticRegion(ElastoplasticRegion&&) noexcept = default;
ElastoplasticRegion::~ElastoplasticRegion() = default;

ElastoplasticRegion::ElastoplasticRegion(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                         AnalysisType type, const J2Hardening& hardening, std::vector<Cell> cells,
                                         std::vector<VariableNode> surface_nodes,
                                         std::vector<PointConstraint> surface_constraints)
    : mesh_(mesh), type_(type), material_(body.material), hardening_(hardening), cells_(std::move(cells)),
      surface_nodes_(std::move(surface_nodes)),
      surface_dofs_(2 * static_cast<Index>(surface_nodes_.size()) + static_cast<Index>(surface_constraints.size())),
      components_(type == AnalysisType::axisymmetric ? 4 : 3) {
  if (!(hardening_.yield_stress > 0.0) || hardening_.isotropic < 0.0 || hardening_.kinematic < 0.0)
    throw Error("body '" + body.name + "': the yield stress must be > 0 and the hardening moduli >= 0");
  // The surface nodes carry data of their kind, the surface constraints theirs (as
  // FactoredBody's variable nodes and constraints).
  auto conditions = resolve_variable_conditions(mesh_, body, type, surface_nodes_, std::move(surface_constraints),
                                                "ElastoplasticRegion");
  conditions_ = std::move(conditions.nodes);
  constraints_ = std::move(conditions.constraints);
  const ElementIntegrator integrator(type, material_);
  const CellKernels kernels(type, material_);
  const Index d = components_;
  auto matrices = assemble_influence_matrices(mesh_, integrator);
  auto system = build_boundary_system(matrices, conditions_, constraints_);
  const Index n = mesh_.node_count(), rows = system.b.size(), m = static_cast<Index>(cells_.size());
  groups_ = 1;
  for (const auto& c : conditions_) groups_ = std::max<Index>(groups_, c.load_group + 1);
  const Index g = groups_, k2 = surface_dofs_, first_cell = g + k2, node_dofs = 2 * static_cast<Index>(surface_nodes_.size());
  const Index first_constraint = static_cast<Index>(constraints_.size()) - (k2 - node_dofs);
  // A surface node's dof carries its datum, but for the radial one on the axis (u_r = p_r = 0).
  const auto surface_of = [&](Index j) -> const VariableNode& { return surface_nodes_[static_cast<std::size_t>(j / 2)]; };
  const auto carries_datum = [&](Index j) {
    return j < node_dofs && !(conditions_[static_cast<std::size_t>(surface_of(j).node)].on_axis && j % 2 == 0);
  };
  const auto is_displacement = [&](Index j) { return j >= node_dofs || surface_of(j).kind == ConditionKind::displacement; };
  // [b_g | T | B]: the body's own data by load group (b_g = G p_g - H u_g, the constraints'
  // rows in group 0, as FactoredBody's), a unit datum at each surface dof, G's column for a
  // traction and -H's for a displacement (the matrices are in the nodes' frames, the surface
  // nodes' global); the cells' domain term at the collocation nodes (the boundary
  // equation's rows), each cell's columns by one thread. Solved in place.
  boundary_unknowns_ = Matrix::Zero(rows, first_cell + d * m);
  for (Index group = 0; group < g; ++group) {
    Vector known_u = Vector::Zero(2 * n), known_p = Vector::Zero(2 * n);
    for (Index i = 0; i < n; ++i)
      for (int c = 0; c < 2; ++c) {
        const auto& condition = conditions_[static_cast<std::size_t>(i)];
        if (condition.load_group == group)
          (condition.kind[c] == ConditionKind::displacement ? known_u : known_p)[2 * i + c] = condition.value[c];
      }
    boundary_unknowns_.block(0, group, 2 * n, 1) = matrices.G * known_p - matrices.H * known_u;
    if (group == 0) boundary_unknowns_.block(2 * n, 0, rows - 2 * n, 1) = system.b.tail(rows - 2 * n);
    for (Index i = 0; i < n; ++i)
      if (conditions_[static_cast<std::size_t>(i)].on_axis) boundary_unknowns_(2 * i, group) = 0.0;
  }
  // A variable constraint's datum is the right-hand side of its equation (the last rows).
  for (Index j = node_dofs; j < k2; ++j) {
    const Index row = 2 * n + first_constraint + (j - node_dofs);
    boundary_unknowns_(row, 0) = 0.0;
    boundary_unknowns_(row, g + j) = 1.0;
  }
  for (Index j = 0; j < k2; ++j) {
    if (!carries_datum(j)) continue;
    const Index dof = 2 * surface_of(j).node + j % 2;
    if (is_displacement(j))
      boundary_unknowns_.block(0, g + j, 2 * n, 1) = -matrices.H.col(dof);
    else
      boundary_unknowns_.block(0, g + j, 2 * n, 1) = matrices.G.col(dof);
    for (Index i = 0; i < n; ++i)
      if (conditions_[static_cast<std::size_t>(i)].on_axis) boundary_unknowns_(2 * i, g + j) = 0.0;
  }
#pragma omp parallel for schedule(dynamic, 1)
  for (Index e = 0; e < m; ++e) {
    const auto sources = cell_and_images(cells_[static_cast<std::size_t>(e)], mesh_.images, kernels.d);
    for (Index i = 0; i < n; ++i) {
      auto block = boundary_unknowns_.block(2 * i, first_cell + d * e, 2, d);
      for (const auto& source : sources)
        block += kernels.displacement(mesh_.nodes[static_cast<std::size_t>(i)].position, source.cell) * source.stress_map;
    }
  }
  const operators::DenseLU lu(std::move(system.A), "the boundary element system of body '" + body.name + "'");
  lu.solve_in_place(boundary_unknowns_);
  // C E = a s + K sigma0: through the boundary (Somigliana's means of the solved (u, t)),
  // then the cells' own fields.
  const std::vector<NodeCondition> unloaded = scaled(conditions_, 0.0);
  Matrix values(4 * n, first_cell + d * m);
  for (Index j = 0; j < first_cell + d * m; ++j) {
    Vector unit = Vector::Zero(g);  // group j's data at amplitude 1, the others' none
    if (j < g) unit[j] = 1.0;
    values.col(j) = boundary_values(boundary_unknowns_.col(j), j < g ? scaled(conditions_, unit) : unloaded, constraints_);
  }
  for (Index j = 0; j < k2; ++j)  // the unit datum itself
    if (carries_datum(j)) values((is_displacement(j) ? 0 : 2 * n) + 2 * surface_of(j).node + j % 2, g + j) = 1.0;
  auto means = cell_mean_points(mesh_, cells_);
  // K = R V + the cells' direct fields, R Somigliana's rows at the cells' means and V the
  // boundary values per unit initial stress: only the columns of cells whose initial stress
  // is not zero are ever used (cell_fields_of, the Newton system's plastic columns), made
  // when a cell first yields (ensure_columns). The O(m^2) operator of the cells that stay
  // elastic is never made: its boundary part is kept as R and V, O(m n).
  boundary_rows_ = mean_somigliana_rows(mesh_, kernels, means);
  load_stress_ = boundary_rows_ * values.leftCols(g);
  data_stress_ = boundary_rows_ * values.middleCols(g, k2);
  cell_values_ = values.rightCols(d * m);
  const bool compress = body.plasticity && body.plasticity->cell_operator == OperatorKind::compressed;
  direct_ = std::make_unique<DirectFields>(CellFieldBlocks(kernels, cells_, std::move(means), mesh_.images, compress));
  if (compress)
    compress_direct_fields(body.name);
  else
    cell_columns_.assign(static_cast<std::size_t>(m), Matrix());
  // The complementary value: traction at a displacement datum, a constraint's reaction.
  surface_response_.resize(k2, d * m);
  for (Index j = 0; j < k2; ++j)
    surface_response_.row(j) =
        j < node_dofs
            ? Matrix(values.block((is_displacement(j) ? 2 * n : 0) + 2 * surface_of(j).node + j % 2, first_cell, 1, d * m))
            : Matrix(boundary_unknowns_.block(2 * n + first_constraint + (j - node_dofs), first_cell, 1, d * m));
  surface_data_ = Vector::Zero(k2);
  amplitudes_ = Vector::Zero(g);
  states_.assign(static_cast<std::size_t>(m), J2State{});
  stress_.assign(static_cast<std::size_t>(m), Mandel::Zero());
  thickness_strain_.assign(static_cast<std::size_t>(m), 0.0);
}

Vector cell_initial_stress(AnalysisType type, const Material& material, const Mandel& plastic_strain) {
  if (type == AnalysisType::plane_stress)
    return in_plane_stiffness(type, material) *
           Eigen::Vector3d(plastic_strain[0], plastic_strain[1], component12(plastic_strain));
  const double G = material.shear_modulus(), nu = material.poisson_ratio;
  const double lambda = 2.0 * G * nu / (1.0 - 2.0 * nu);
  const double trace = plastic_strain.head<3>().sum();
  Vector sigma0(type == AnalysisType::axisymmetric ? 4 : 3);
  sigma0[0] = lambda * trace + 2 * G * plastic_strain[0];
  sigma0[1] = lambda * trace + 2 * G * plastic_strain[1];
  sigma0[2] = 2 * G * component12(plastic_strain);
  if (type == AnalysisType::axisymmetric) sigma0[3] = lambda * trace + 2 * G * plastic_strain[2];
  return sigma0;
}

Vector ElastoplasticRegion::initial_stresses() const {
  const Index d = components_;
  Vector sigma0(d * static_cast<Index>(cells_.size()));
  for (std::size_t e = 0; e < cells_.size(); ++e)
    sigma0.segment(d * static_cast<Index>(e), d) = cell_initial_stress(type_, material_, states_[e].plastic_strain);
  return sigma0;
}

ElastoplasticState ElastoplasticRegion::state() const {
  return {states_, stress_, thickness_strain_, surface_data_, amplitudes_};
}

void ElastoplasticRegion::restore(const ElastoplasticState& state) {
  states_ = state.states, stress_ = state.stress, thickness_strain_ = state.thickness_strain;
  surface_data_ = state.surface_data, amplitudes_ = state.amplitudes;
}

// The residual F(E) of an increment to the load groups' `amplitudes` with the surface data `data`,
// with each cell's update, its initial stress and d sigma0 / d E (the Newton system's blocks).
struct ElastoplasticRegion::Evaluation {
  std::vector<J2Update> updates;
  std::vector<Matrix> slope;
  Vector sigma0;
  Vector F;
  double norm = 0.0;  // max |F| / (Y / E)
  Index worst = 0;    // the cell where it is largest
};

// The cells' direct fields D as a hierarchical matrix: rows and columns at the cells'
// centroids (d unknowns each), each block's entries from the cells' d x d blocks. Its
// accuracy is that of the kernels' own quadrature (their far rules switch at steps of about
// 1e-8 to 1e-6): 1e-10 kept ranks 1.5 times as high (compression ratio 0.20 against 0.14 at
// 4 162 cells) for no accuracy the kernels have.
void ElastoplasticRegion::compress_direct_fields(const std::string& name) {
  constexpr double kCellAccuracy = 1e-8;
  const Index d = components_, m = static_cast<Index>(cells_.size());
  std::vector<Vec2> points;
  for (const auto& centroid : direct_->blocks.centroids())
    for (Index k = 0; k < d; ++k) points.push_back(centroid);
  // hmat-oss asks for single rows and columns (ACA+), each entry of which is one of a d x d
  // block, made whole by one kernel call: the blocks made are kept (up to kKeptBlocks, then
  // forgotten all at once) for the rows and columns of the same cells that follow. The
  // row pieces assemble on separate threads and share them (the blocks are pure).
  constexpr std::size_t kKeptBlocks = 1 << 16;
  struct BlockMemo {
    std::mutex mutex;
    std::unordered_map<std::uint64_t, Matrix> blocks;
  } memo;
  const CellFieldBlocks& blocks = direct_->blocks;
  const operators::BlockFunction entries = [&blocks, &memo, d, m](const std::vector<Index>& rows,
                                                                  const std::vector<Index>& cols, double* out) {
    // The distinct cells of the rows and columns.
    const auto distinct = [d](const std::vector<Index>& unknowns, std::vector<Index>& slot) {
      std::vector<Index> cells;
      for (const Index u : unknowns) {
        if (cells.empty() || cells.back() != u / d) cells.push_back(u / d);
        slot.push_back(static_cast<Index>(cells.size()) - 1);
      }
      return cells;
    };
    std::vector<Index> row_slot, col_slot;
    const auto row_cells = distinct(rows, row_slot), col_cells = distinct(cols, col_slot);
    const auto pairs = static_cast<Index>(row_cells.size() * col_cells.size());
    std::vector<Matrix> pair_blocks(static_cast<std::size_t>(pairs));
    const auto key_of = [&](Index k) {  // pair k: row cell k % rows, column cell k / rows
      const auto u = static_cast<std::size_t>(k);
      return static_cast<std::uint64_t>(row_cells[u % row_cells.size()]) * static_cast<std::uint64_t>(m) +
             static_cast<std::uint64_t>(col_cells[u / row_cells.size()]);
    };
    std::vector<Index> missing;
    {
      std::lock_guard<std::mutex> lock(memo.mutex);
      for (Index k = 0; k < pairs; ++k) {
        const auto found = memo.blocks.find(key_of(k));
        if (found != memo.blocks.end()) pair_blocks[static_cast<std::size_t>(k)] = found->second;
        else missing.push_back(k);
      }
    }
#pragma omp parallel for schedule(dynamic, 4)
    for (std::size_t j = 0; j < missing.size(); ++j) {
      const auto k = static_cast<std::size_t>(missing[j]);
      pair_blocks[k] = blocks.block(static_cast<std::size_t>(row_cells[k % row_cells.size()]),
                                    static_cast<std::size_t>(col_cells[k / row_cells.size()]));
    }
    {
      std::lock_guard<std::mutex> lock(memo.mutex);
      if (memo.blocks.size() + missing.size() > kKeptBlocks) memo.blocks.clear();
      for (const Index k : missing) {
        memo.blocks.emplace(key_of(k), pair_blocks[static_cast<std::size_t>(k)]);
      }
    }
    const auto R = static_cast<Index>(rows.size());
    for (Index c = 0; c < static_cast<Index>(cols.size()); ++c)
      for (Index r = 0; r < R; ++r) {
        const auto k = static_cast<std::size_t>(row_slot[static_cast<std::size_t>(r)]) +
                       row_cells.size() * static_cast<std::size_t>(col_slot[static_cast<std::size_t>(c)]);
        out[r + c * R] = pair_blocks[k](rows[static_cast<std::size_t>(r)] % d, cols[static_cast<std::size_t>(c)] % d);
      }
  };
  // The cells' components interleaved, not apart (HMatrixOptions::row_component): hmat-oss's
  // check of every block of the 1 090-cell Brinell D found none above 10 times the accuracy
  // (the worst 9.9e-8 at 1e-8; 3.8e-8 apart), where apart cost 50 % more set-up at 4 162
  // cells (145 s against 97 s). The boundary's blocks, with their collinear nodes, need it.
  direct_->compressed = std::make_unique<operators::RowPartitionedHMatrix>(points, points, entries,
                                                             operators::HMatrixOptions::with_accuracy(kCellAccuracy),
                                                             "the cells' direct fields of body '" + name + "'");
  direct_->position.assign(static_cast<std::size_t>(m), -1);
}

bool ElastoplasticRegion::compressed_cells() const { return direct_->compressed != nullptr; }

void ElastoplasticRegion::ensure_columns(const std::vector<Index>& cells) const {
  const Index d = components_;
  std::vector<Index> missing;
  for (const Index e : cells)
    if (compressed_cells() ? direct_->position[static_cast<std::size_t>(e)] < 0
                           : cell_columns_[static_cast<std::size_t>(e)].size() == 0)
      missing.push_back(e);
  if (missing.empty()) return;
  if (!compressed_cells()) {
    // The boundary's part of all of them in one product (R times their columns of V).
    Matrix V(cell_values_.rows(), d * static_cast<Index>(missing.size()));
    for (std::size_t j = 0; j < missing.size(); ++j)
      V.middleCols(d * static_cast<Index>(j), d) = cell_values_.middleCols(d * missing[j], d);
    const Matrix RV = boundary_rows_ * V;
    for (std::size_t j = 0; j < missing.size(); ++j)
      cell_columns_[static_cast<std::size_t>(missing[j])] = RV.middleCols(d * static_cast<Index>(j), d);
    add_cell_fields(direct_->blocks, d, missing, cell_columns_);
    return;
  }
  // The kept block grown by the missing cells' rows and columns: R_kept V_new and
  // R_new V_old, plus the direct fields as the hierarchical matrix holds them (no kernel
  // call: the Newton system then has the products' own D).
  DirectFields& f = *direct_;
  const auto old = static_cast<Index>(f.kept.size());
  for (const Index e : missing) {
    f.position[static_cast<std::size_t>(e)] = static_cast<Index>(f.kept.size());
    f.kept.push_back(e);
  }
  const auto total = static_cast<Index>(f.kept.size());
  Matrix R(d * total, boundary_rows_.cols()), V(cell_values_.rows(), d * total);
  for (Index i = 0; i < total; ++i) {
    const Index e = f.kept[static_cast<std::size_t>(i)];
    R.middleRows(d * i, d) = boundary_rows_.middleRows(d * e, d);
    V.middleCols(d * i, d) = cell_values_.middleCols(d * e, d);
  }
  Matrix grown(d * total, d * total);
  grown.topLeftCorner(d * old, d * old) = f.block;
  f.block = Matrix();
  grown.rightCols(d * (total - old)).noalias() = R * V.rightCols(d * (total - old));
  grown.bottomLeftCorner(d * (total - old), d * old).noalias() = R.bottomRows(d * (total - old)) * V.leftCols(d * old);
  std::vector<Index> unknowns;  // of the kept cells, in their order
  for (const Index e : f.kept)
    for (Index k = 0; k < d; ++k) unknowns.push_back(d * e + k);
  const std::vector<Index> old_unknowns(unknowns.begin(), unknowns.begin() + d * old),
      new_unknowns(unknowns.begin() + d * old, unknowns.end());
  grown.rightCols(d * (total - old)) += f.compressed->entries(unknowns, new_unknowns);
  grown.bottomLeftCorner(d * (total - old), d * old) += f.compressed->entries(new_unknowns, old_unknowns);
  f.block = std::move(grown);
}

Eigen::Ref<const Matrix> ElastoplasticRegion::operator_block(Index c, Index e) const {
  const Index d = components_;
  if (!compressed_cells()) return cell_columns_[static_cast<std::size_t>(e)].middleRows(d * c, d);
  const auto& f = *direct_;
  return f.block.block(d * f.position[static_cast<std::size_t>(c)], d * f.position[static_cast<std::size_t>(e)], d, d);
}

Matrix ElastoplasticRegion::cell_operator() const {
  const Index d = components_, m = static_cast<Index>(cells_.size());
  if (compressed_cells()) return boundary_rows_ * cell_values_ + direct_->compressed->apply(Matrix::Identity(d * m, d * m));
  std::vector<Index> all(cells_.size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<Index>(e);
  ensure_columns(all);
  Matrix K(d * m, d * m);
  for (Index e = 0; e < m; ++e) K.middleCols(d * e, d) = cell_columns_[static_cast<std::size_t>(e)];
  return K;
}

Vector ElastoplasticRegion::cell_fields_of(const Vector& sigma0) const {
  const Index d = components_;
  std::vector<Index> sources;
  for (Index e = 0; e < static_cast<Index>(cells_.size()); ++e)
    if (!sigma0.segment(d * e, d).isZero(0.0)) sources.push_back(e);
  if (compressed_cells()) {  // R (V sigma0) + D sigma0
    Vector values = Vector::Zero(cell_values_.rows());
    for (const Index e : sources) values.noalias() += cell_values_.middleCols(d * e, d) * sigma0.segment(d * e, d);
    Vector out = boundary_rows_ * values;
    if (!sources.empty()) out += direct_->compressed->apply(sigma0).col(0);
    return out;
  }
  ensure_columns(sources);
  Vector out = Vector::Zero(d * static_cast<Index>(cells_.size()));
  for (const Index e : sources) out.noalias() += cell_columns_[static_cast<std::size_t>(e)] * sigma0.segment(d * e, d);
  return out;
}

ElastoplasticRegion::Evaluation ElastoplasticRegion::evaluate(const Vector& E, const Vector& amplitudes, const Vector& data,
                                                              const std::vector<plasticity::J2Hold>& held,
                                                              const CommittedFields& committed) const {
  const Index m = static_cast<Index>(cells_.size()), d = components_;
  const CellKernels kernels(type_, material_);
  const Matrix C = kernels.stiffness();
  const Matrix compliance = C.inverse();
  // The stress and its tangent on the tensor components from the Mandel update:
  // sigma_12 = m_3 / sqrt2, and m_3 = sqrt2 E_12 in the strain.
  const std::vector<int> rows = kernels.mandel_rows();
  Vector out_scale = Vector::Ones(d), in_scale = Vector::Ones(d);
  out_scale[2] = 1.0 / kSqrt2, in_scale[2] = kSqrt2;  // the 12 (rz) component is third
  Evaluation out;
  out.updates.resize(static_cast<std::size_t>(m));
  out.slope.resize(static_cast<std::size_t>(m));
  Vector sigma0(d * m);
  for (Index e = 0; e < m; ++e) {
    const auto k = static_cast<std::size_t>(e);
    auto& update = out.updates[k];
    const Vector strain = E.segment(d * e, d);
    update = type_ == AnalysisType::plane_stress
                 ? plasticity::j2_update_plane_stress(material_, hardening_, states_[k],
                                                      kernels.strain_of(strain, thickness_strain_[k]), 1e-12, held[k])
                 : j2_update(material_, hardening_, states_[k], kernels.strain_of(strain), held[k]);
    Vector stress(d);
    Matrix tangent(d, d);
    for (Index i = 0; i < d; ++i) {
      stress[i] = out_scale[i] * update.stress[rows[static_cast<std::size_t>(i)]];
      for (Index j = 0; j < d; ++j)
        tangent(i, j) = out_scale[i] * update.tangent(rows[static_cast<std::size_t>(i)], rows[static_cast<std::size_t>(j)]) * in_scale[j];
    }
    // sigma = C E - sigma0: the initial stress the update leaves (an elastic cell's the
    // committed one, exactly: its field is then not taken again), and its slope.
    sigma0.segment(d * e, d) = update.plastic ? Vector(C * strain - stress) : Vector(committed.sigma0.segment(d * e, d));
    out.slope[k] = C - tangent;
  }
  // C E as the boundary's and the cells' fields give it; the cells' fields as the committed
  // ones plus those of the cells whose initial stress moved (the plastic ones: a few of
  // all, where the whole product was half the run's time).
  const Vector target = load_stress_ * amplitudes.head(groups_) + data_stress_ * data + committed.field +
                        cell_fields_of(sigma0 - committed.sigma0);
  out.sigma0 = sigma0;
  out.F.resize(d * m);
  for (Index e = 0; e < m; ++e) out.F.segment(d * e, d) = E.segment(d * e, d) - compliance * target.segment(d * e, d);
  out.norm = m > 0 ? out.F.cwiseAbs().maxCoeff(&out.worst) / (hardening_.yield_stress / material_.young_modulus) : 0.0;
  out.worst /= d;
  return out;
}

namespace {

// The plastic cells' slopes S_e = d sigma0 / d E as P_e Q_e^T of their ranks r_e (by their
// singular values; below 1e-12 of the largest or 1e-14 |C|, dropped). J2 leaves a
// volumetric strain elastic, so in axisymmetry (d = 4) r_e = 3; in plane strain and
// plane stress r_e = d.
struct SlopeFactors {
  std::vector<Matrix> P, Q;
  std::vector<Index> offset;  // of each plastic cell's reduced unknowns; back(): their count
};

SlopeFactors factor_slopes(const std::vector<Matrix>& slopes, const std::vector<Index>& plastic,
                           const Matrix& compliance) {
  const double stiffness = compliance.inverse().norm();
  SlopeFactors out;
  out.offset.assign(plastic.size() + 1, 0);
  for (std::size_t k = 0; k < plastic.size(); ++k) {
    const Eigen::JacobiSVD<Matrix> svd(slopes[static_cast<std::size_t>(plastic[k])],
                                       Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Vector& sigma = svd.singularValues();
    const double floor = std::max(1e-12 * sigma[0], 1e-14 * stiffness);
    Index rank = 0;
    while (rank < sigma.size() && sigma[rank] > floor) ++rank;
    out.P.push_back(svd.matrixU().leftCols(rank) * sigma.head(rank).asDiagonal());
    out.Q.push_back(svd.matrixV().leftCols(rank));
    out.offset[k + 1] = out.offset[k] + rank;
  }
  return out;
}

// I - Q^T C^-1 K_PP P, K_PP's d x d blocks from block(i, j) (plastic cells i, j), in
// panels of columns: C^-1 K_PP P_j first, then Q_i^T times the panel's rows.
template <class Block>
Matrix reduced_newton_matrix(const SlopeFactors& factors, const Matrix& compliance, Block&& block) {
  constexpr Index kPanelCells = 64;
  const Index p = static_cast<Index>(factors.P.size()), d = compliance.rows(), reduced = factors.offset.back();
  std::vector<Matrix> W;  // Q_i^T C^-1
  for (const Matrix& Q : factors.Q) W.push_back(Q.transpose() * compliance);
  Matrix J = Matrix::Identity(reduced, reduced);
  for (Index j0 = 0; j0 < p; j0 += kPanelCells) {
    const Index j1 = std::min(p, j0 + kPanelCells);
    const Index first = factors.offset[static_cast<std::size_t>(j0)];
    const Index columns = factors.offset[static_cast<std::size_t>(j1)] - first;
    Matrix panel(d * p, columns);
    for (Index j = j0; j < j1; ++j) {
      const Matrix& P = factors.P[static_cast<std::size_t>(j)];
      for (Index i = 0; i < p; ++i)
        panel.block(d * i, factors.offset[static_cast<std::size_t>(j)] - first, d, P.cols()).noalias() = block(i, j) * P;
    }
    for (Index i = 0; i < p; ++i) {
      const auto k = static_cast<std::size_t>(i);
      J.block(factors.offset[k], first, W[k].rows(), columns).noalias() -= W[k] * panel.middleRows(d * i, d);
    }
  }
  return J;
}

}  // namespace

// Newton from the elastic predictor, with a backtracking line search on |F| (the radial
// return's kinks make full steps cycle near the elastic-plastic boundary). With a contact,
// each iteration solves it on the linearised plastic response (Newton's step in the
// surface data), and the increment ends when F and the data's change both vanish.
struct ElastoplasticIncrement::State {
  State(ElastoplasticRegion& r, Vector a, int iterations, double tol, bool contact)
      : region(r), amplitudes(std::move(a)), max_iterations(iterations), tolerance(tol), in_contact(contact),
        m(static_cast<Index>(r.cells_.size())), d(r.components_) {}
  ElastoplasticRegion& region;
  Vector amplitudes;  // per load group
  int max_iterations;
  double tolerance;
  bool in_contact;
  Index m, d;
  Matrix compliance;
  ElastoplasticRegion::CommittedFields committed;
  Vector E, data;
  Matrix strain_per_datum;  // C^-1 H: the strain per unit surface datum, through the boundary
  // Cells that cycled between elastic and plastic are held on the yield surface, and
  // released to the elastic state where the solution unloads them (settle_held).
  std::vector<plasticity::J2Hold> held;
  std::vector<char> last_state;
  int settled = 0;  // passes of settle_held that changed a cell
  std::vector<int> flips;  // changes of state from iteration to iteration
  ElastoplasticRegion::Evaluation current;
  int iteration = 0, stalled_for = 0, newton_iterations = 0;
  double last_norm = 0.0;
  // The present linearisation: the plastic cells, the initial stresses' change S dE_P of
  // Newton's step at fixed surface data and its right-hand side r, that change per unit
  // change of the data (SZ), and the surface's affine response u0 + F t (the complementary
  // values: displacements at traction data, tractions at displacement data).
  std::vector<Index> plastic;
  Matrix SZ, F;
  Vector source_step, rhs, u0;
};

ElastoplasticIncrement::ElastoplasticIncrement(ElastoplasticRegion& region, const Vector& amplitudes, int max_iterations,
                                               double tolerance, bool in_contact)
    : s_(std::make_unique<State>(region, amplitudes, max_iterations, tolerance, in_contact)) {
  if (amplitudes.size() < region.groups_) throw std::logic_error("ElastoplasticIncrement: an amplitude per load group");
  State& s = *s_;
  const Index m = s.m, d = s.d;
  s.compliance = CellKernels(region.type_, region.material_).stiffness().inverse();
  s.data = region.surface_data_;
  // The elastic predictor: the new load with the plastic strains of the last increment.
  s.committed.sigma0 = region.initial_stresses();
  s.committed.field = region.cell_fields_of(s.committed.sigma0);
  s.E.resize(d * m);
  const Vector target = region.load_stress_ * s.amplitudes.head(region.groups_) + region.data_stress_ * s.data +
                        s.committed.field;
  for (Index e = 0; e < m; ++e) s.E.segment(d * e, d) = s.compliance * target.segment(d * e, d);
  s.strain_per_datum.resize(d * m, region.surface_dofs_);
  for (Index e = 0; e < m; ++e)
    s.strain_per_datum.middleRows(d * e, d) = s.compliance * region.data_stress_.middleRows(d * e, d);
  s.held.assign(static_cast<std::size_t>(m), plasticity::J2Hold::none);
  s.last_state.assign(static_cast<std::size_t>(m), 0);
  s.flips.assign(static_cast<std::size_t>(m), 0);
  s.current = region.evaluate(s.E, s.amplitudes, s.data, s.held, s.committed);
  s.last_norm = s.current.norm;
}

ElastoplasticIncrement::~ElastoplasticIncrement() = default;

double ElastoplasticIncrement::residual() const { return s_->current.norm; }
int ElastoplasticIncrement::iteration() const { return s_->iteration; }
bool ElastoplasticIncrement::converged() const { return s_->current.norm <= s_->tolerance; }
const Vector& ElastoplasticIncrement::data() const { return s_->data; }
const Vector& ElastoplasticIncrement::surface_offset() const { return s_->u0; }
const Matrix& ElastoplasticIncrement::surface_flexibility() const { return s_->F; }

// An increment whose residual has stalled (above the tolerance, 4 iterations running each
// less than 5 % below the last and not a jump: a new held cell or a contact update) is
// given up at once: its halves converge, and in the Brinell cycle every stall ran on to
// the iteration limit.
bool ElastoplasticIncrement::linearise(std::string& failure) {
  State& s = *s_;
  ElastoplasticRegion& region = s.region;
  const Index m = s.m, d = s.d;
  constexpr int kStalledIterations = 4;
  const bool slow = s.iteration > 0 && s.current.norm > s.tolerance && s.current.norm > 0.95 * s.last_norm &&
                    s.current.norm < 1.5 * s.last_norm;
  s.stalled_for = slow ? s.stalled_for + 1 : 0;
  s.last_norm = s.current.norm;
  // A cell that went back to the state it left is held (one change is the plastic zone
  // growing or an unloading; a return is a cycle).
  bool newly_held = false;
  for (Index e = 0; e < m; ++e) {
    const auto k = static_cast<std::size_t>(e);
    const char state = s.current.updates[k].plastic ? 1 : 0;
    if (s.iteration > 0 && state != s.last_state[k] && ++s.flips[k] >= 2 && s.held[k] == plasticity::J2Hold::none)
      s.held[k] = plasticity::J2Hold::on_surface, newly_held = true;
    s.last_state[k] = state;
  }
  if (newly_held) s.current = region.evaluate(s.E, s.amplitudes, s.data, s.held, s.committed);
  const bool stalled = s.stalled_for >= kStalledIterations;
  if (s.iteration == s.max_iterations || stalled || !std::isfinite(s.current.norm)) {
    const Vec2 at = region.cells_[static_cast<std::size_t>(s.current.worst)].centroid();
    std::ostringstream message;
    message << "Newton on the cells' strains did not converge in " << s.iteration
            << (stalled ? " iterations (stalled: residual " : " iterations (residual ") << s.current.norm
            << " of Y/E, largest at cell " << s.current.worst << ", (" << at.x() << ", " << at.y() << "))";
    failure = message.str();
    return false;
  }
  // J = I - C^-1 K diag(d sigma0 / d E). An elastic cell's slope is 0: its columns are
  // the identity's, so the plastic cells' block is solved alone and every cell's step
  // follows, dE = r + C^-1 K_{.P} S_P dE_P, for the right-hand side r = -F (+ C^-1 H dt).
  s.plastic.clear();
  for (Index e = 0; e < m; ++e)
    if (!s.current.slope[static_cast<std::size_t>(e)].isZero(0.0)) s.plastic.push_back(e);
  const Index p = static_cast<Index>(s.plastic.size());
  region.ensure_columns(s.plastic);
  // With S_P = P Q^T and y = Q^T dE_P, J_PP dE_P = r_P is (I - Q^T C^-1 K_PP P) y = Q^T r_P:
  // sum r_e unknowns (3/4 of d p in axisymmetry, 0.42 of the LU's flops), and S_P dE_P = P y
  // is all the step needs.
  const SlopeFactors factors = factor_slopes(s.current.slope, s.plastic, s.compliance);
  const std::vector<Matrix>&P = factors.P, &Q = factors.Q;
  const std::vector<Index>& offset = factors.offset;
  const Index reduced = offset.back();
  Matrix J = reduced_newton_matrix(factors, s.compliance, [&](Index i, Index j) {
    return region.operator_block(s.plastic[static_cast<std::size_t>(i)], s.plastic[static_cast<std::size_t>(j)]);
  });
  const Index surface = s.in_contact ? region.surface_dofs_ : 0;
  Matrix reduced_rhs(reduced, 1 + surface);  // Q^T [-F | C^-1 H] on the plastic rows
  for (Index i = 0; i < p; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Index e = s.plastic[k];
    reduced_rhs.block(offset[k], 0, Q[k].cols(), 1).noalias() = -Q[k].transpose() * s.current.F.segment(d * e, d);
    if (s.in_contact)
      reduced_rhs.block(offset[k], 1, Q[k].cols(), surface).noalias() =
          Q[k].transpose() * s.strain_per_datum.middleRows(d * e, d);
  }
  if (reduced > 0) {
    const operators::DenseLU lu(std::move(J), "the elastoplastic Newton system");
    lu.solve_in_place(reduced_rhs);
  }
  // S_P dE_P = P y, and per unit change of the data.
  Matrix sources(d * p, 1 + surface);
  for (Index j = 0; j < p; ++j) {
    const auto k = static_cast<std::size_t>(j);
    sources.middleRows(d * j, d).noalias() = P[k] * reduced_rhs.middleRows(offset[k], P[k].cols());
  }
  s.source_step = sources.col(0);
  s.rhs = -s.current.F;
  if (s.in_contact) {
    // The cells' complementary values at the surface as the step moves the data from t to t':
    // G (sigma0 + S dE_P(t')), S dE_P(t') = S dE_P(t) + SZ (t' - t).
    Matrix G(surface, d * p);
    for (Index j = 0; j < p; ++j)
      G.middleCols(d * j, d) = region.surface_response_.middleCols(d * s.plastic[static_cast<std::size_t>(j)], d);
    s.SZ = sources.rightCols(surface);
    s.F = G * s.SZ;
    s.u0 = region.surface_response_ * s.current.sigma0 + G * (s.source_step - s.SZ * s.data);
  }
  return true;
}

// The data to 1e-7 of the largest of their kind (tractions, bond displacements): near a
// limit load the linearised contact is ill-conditioned (a perfectly plastic block at
// -2Y/sqrt3: its tractions wander by 3e-9 from iteration to iteration while F stays at
// round-off).
bool ElastoplasticIncrement::converged_with(const Vector& next) const {
  if (!converged()) return false;
  const auto& nodes = s_->region.surface_nodes_;
  const auto kind_of = [&](Index j) {  // the variable constraints' data after the nodes' are displacements
    return j < 2 * static_cast<Index>(nodes.size()) ? nodes[static_cast<std::size_t>(j / 2)].kind
                                                    : ConditionKind::displacement;
  };
  for (const ConditionKind kind : {ConditionKind::traction, ConditionKind::displacement}) {
    double scale = 0.0, moved = 0.0;
    for (Index j = 0; j < next.size(); ++j) {
      if (kind_of(j) != kind) continue;
      scale = std::max(scale, std::abs(next[j]));
      moved = std::max(moved, std::abs(next[j] - s_->data[j]));
    }
    if (moved > 1e-7 * scale) return false;
  }
  return true;
}

void ElastoplasticIncrement::step(const Vector& next) {
  State& s = *s_;
  ElastoplasticRegion& region = s.region;
  const Index d = s.d;
  if (s.in_contact) {
    const Vector change = next - s.data;
    s.source_step += s.SZ * change;
    s.rhs += s.strain_per_datum * change;
    s.data = next;
    s.current = region.evaluate(s.E, s.amplitudes, s.data, s.held, s.committed);  // the line search's reference
  }
  // dE = r + C^-1 K_{.P} S_P dE_P: one product over the plastic cells' columns (on the
  // plastic rows it is the solved step itself).
  Vector sources = Vector::Zero(s.m * d);
  for (std::size_t j = 0; j < s.plastic.size(); ++j)
    sources.segment(d * s.plastic[j], d) = s.source_step.segment(d * static_cast<Index>(j), d);
  const Vector moved = region.cell_fields_of(sources);
  Matrix step = s.rhs;
  for (Index c = 0; c < s.m; ++c) step.middleRows(d * c, d) += s.compliance * moved.segment(d * c, d);
  double fraction = 1.0;
  auto next_evaluation = region.evaluate(s.E + step.col(0), s.amplitudes, s.data, s.held, s.committed);
  constexpr int kHalvings = 10;
  for (int k = 0; k < kHalvings && !(next_evaluation.F.norm() < (1.0 - 1e-4 * fraction) * s.current.F.norm()); ++k) {
    fraction *= 0.5;
    next_evaluation = region.evaluate(s.E + fraction * step.col(0), s.amplitudes, s.data, s.held, s.committed);
  }
  s.E += fraction * step.col(0);
  s.current = std::move(next_evaluation);
  ++s.iteration;
  ++s.newton_iterations;
}

// A held cell's state is the Newton's device, not the material's: once Newton has converged,
// a cell held on the yield surface with a negative plastic increment (the solution unloads
// it) is held elastic instead, and a cell held elastic whose trial lies outside the yield
// surface is held on it again; Newton then goes on. A primal active-set pass, at most
// kSettlePasses times: what is left is reported (IncrementReport::held_increment).
bool ElastoplasticIncrement::settle_held() {
  constexpr int kSettlePasses = 4;
  State& s = *s_;
  ElastoplasticRegion& region = s.region;
  if (s.settled >= kSettlePasses) return false;
  const double yield = region.hardening_.yield_stress;
  const double strain_tolerance = 1e-8 * yield / region.material_.young_modulus;
  bool changed = false;
  for (std::size_t k = 0; k < s.held.size(); ++k) {
    const auto& update = s.current.updates[k];
    if (s.held[k] == plasticity::J2Hold::on_surface && update.plastic_increment < -strain_tolerance)
      s.held[k] = plasticity::J2Hold::elastic, changed = true;
    else if (s.held[k] == plasticity::J2Hold::elastic && update.yield_function_trial > 1e-8 * yield)
      s.held[k] = plasticity::J2Hold::on_surface, changed = true;
  }
  if (!changed) return false;
  ++s.settled;
  s.current = region.evaluate(s.E, s.amplitudes, s.data, s.held, s.committed);
  return true;
}

void ElastoplasticIncrement::commit(IncrementReport& report) {
  State& s = *s_;
  ElastoplasticRegion& region = s.region;
  report.newton_iterations += s.newton_iterations;
  report.residual = s.current.norm;
  const double strain_scale = region.hardening_.yield_stress / region.material_.young_modulus;
  for (Index e = 0; e < s.m; ++e) {
    const auto k = static_cast<std::size_t>(e);
    const auto& update = s.current.updates[k];
    report.plastic_cells += update.plastic ? 1 : 0;
    if (s.held[k] != plasticity::J2Hold::none) {
      ++report.held_cells;
      report.held_increment = std::min(report.held_increment, update.plastic_increment / strain_scale);
    }
    region.states_[k] = update.state;
    region.stress_[k] = update.stress;
    region.thickness_strain_[k] = update.strain[2];
  }
  region.surface_data_ = s.data;
  region.amplitudes_ = s.amplitudes;
}

// Without contact: Newton's steps at the surface data of the last increment. Commits
// the state when it converges; false otherwise (`failure` says where).
bool ElastoplasticRegion::solve_increment(double amplitude, int max_iterations, double tolerance,
                                          IncrementReport& report, std::string& failure) {
  ElastoplasticIncrement increment(*this, Vector::Constant(1, amplitude), max_iterations, tolerance, false);
  while (!increment.converged() || increment.settle_held()) {
    if (!increment.linearise(failure)) {
      report.residual = increment.residual();
      return false;
    }
    increment.step(increment.data());
  }
  increment.commit(report);
  return true;
}

IncrementReport ElastoplasticRegion::advance(double amplitude, int max_iterations, double tolerance) {
  IncrementReport report;
  report.amplitude = amplitude;
  if (groups_ > 1) throw std::logic_error("ElastoplasticRegion::advance: one load group (the data amplitude)");
  const double from = amplitudes_[0];
  // An increment that fails is cut in halves, each solved in turn, down to kMaxCuts levels.
  constexpr int kMaxCuts = 6;
  std::vector<std::pair<double, int>> targets{{amplitude, 0}};  // (amplitude, cut level), last first
  std::string failure;
  while (!targets.empty()) {
    const auto [target, level] = targets.back();
    IncrementReport part;
    if (solve_increment(target, max_iterations, tolerance, part, failure)) {
      targets.pop_back();
      report.newton_iterations += part.newton_iterations;
      report.residual = part.residual;
      report.plastic_cells = std::max(report.plastic_cells, part.plastic_cells);
      report.held_cells += part.held_cells;
      report.held_increment = std::min(report.held_increment, part.held_increment);
      continue;
    }
    if (level == kMaxCuts) {
      std::ostringstream message;
      message << "elastoplastic increment from load amplitude " << from << " to " << amplitude << ": at the step to "
              << target << " (the increment cut " << level << " times in halves) " << failure
              << "; take smaller load increments";
      throw SolverError(message.str(), SolverFailure{"elastoplastic increment", max_iterations, part.residual, -1, target});
    }
    ++report.cuts;
    targets.back().second = level + 1;
    targets.push_back({0.5 * (amplitudes_[0] + target), level + 1});
  }
  return report;
}

BoundarySolution ElastoplasticRegion::boundary_solution() const {
  const Index m = static_cast<Index>(cells_.size());
  const Index d = components_;
  Vector coefficients(groups_ + surface_dofs_ + d * m);
  coefficients << amplitudes_.head(groups_), surface_data_, initial_stresses();
  BoundarySolution solution =
      recover_boundary_values(boundary_unknowns_ * coefficients, scaled(conditions_, amplitudes_), constraints_);
  for (Index j = 0; j < 2 * static_cast<Index>(surface_nodes_.size()); ++j) {
    const auto& surface = surface_nodes_[static_cast<std::size_t>(j / 2)];
    const auto node = static_cast<std::size_t>(surface.node);
    if (conditions_[node].on_axis && j % 2 == 0) continue;
    (surface.kind == ConditionKind::displacement ? solution.displacement : solution.traction)[node][j % 2] =
        surface_data_[j];
  }
  return solution;
}

struct PlasticCellFields::Sources {
  std::vector<std::vector<CellImage>> of_cell;  // each cell with its images
};

PlasticCellFields::PlasticCellFields(AnalysisType type, const Material& material, const geometry::BoundaryMesh& mesh,
                                     std::vector<Cell> cells, const std::vector<Mandel>& plastic_strains)
    : type_(type), material_(material), scale_(mesh.scale), cells_(std::move(cells)),
      sources_(std::make_unique<Sources>()) {
  if (plastic_strains.size() != cells_.size())
    throw std::logic_error("PlasticCellFields: one plastic strain per cell");
  const int d = type == AnalysisType::axisymmetric ? 4 : 3;
  for (std::size_t e = 0; e < cells_.size(); ++e) {
    sources_->of_cell.push_back(cell_and_images(cells_[e], mesh.images, d));
    initial_stresses_.push_back(cell_initial_stress(type, material, plastic_strains[e]));
    plastic33_.push_back(plastic_strains[e][2]);
  }
}

PlasticCellFields::~PlasticCellFields() = default;
PlasticCellFields::PlasticCellFields(PlasticCellFields&&) noexcept = default;

void PlasticCellFields::add_at(const Vec2& point, Vec2& u, StressTensor& stress) const {
  const CellKernels kernels(type_, material_);
  const auto& sources = sources_->of_cell;
  // Off every edge: the fields' edge integrals are singular on them.
  const auto on_an_edge = [&](const Vec2& x) {
    const double tolerance = 1e-10 * scale_;
    for (const auto& images : sources)
      for (const auto& source : images) {
        const auto& v = source.cell.vertices;
        for (std::size_t k = 0; k < v.size(); ++k) {
          const Vec2 a = v[k], b = v[(k + 1) % v.size()];
          const double f = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
          if ((x - (a + f * (b - a))).norm() <= tolerance) return true;
        }
      }
    return false;
  };
  Vec2 x = point;
  if (on_an_edge(x)) x += 1e-8 * scale_ * Vec2(1.0, 1.0).normalized();
  Vector c_eps = Vector::Zero(kernels.d);
  double plastic33 = 0.0;
  for (std::size_t e = 0; e < cells_.size(); ++e) {
    const Vector& sigma0 = initial_stresses_[e];
    if (sigma0.isZero(0.0)) continue;
    for (const auto& source : sources[e]) {
      u += kernels.displacement(x, source.cell) * (source.stress_map * sigma0);
      c_eps += kernels.stress(x, source.cell) * (source.stress_map * sigma0);
    }
    if (cells_[e].contains(x)) c_eps -= sigma0, plastic33 = plastic33_[e];
  }
  stress.s11 += c_eps[0], stress.s22 += c_eps[1], stress.s12 += c_eps[2];
  if (kernels.axisymmetric())
    stress.s33 += c_eps[3];  // the hoop stress, its own component
  else if (type_ == AnalysisType::plane_strain)
    stress.s33 += material_.poisson_ratio * (c_eps[0] + c_eps[1]) - material_.young_modulus * plastic33;
}

PlasticCellFields ElastoplasticRegion::cell_fields() const {
  std::vector<Mandel> plastic;
  for (const auto& state : states_) plastic.push_back(state.plastic_strain);
  return PlasticCellFields(type_, material_, mesh_, cells_, plastic);
}

}  // namespace bemcontact::bem
