#include "bemcontact/contact/condensed.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Sparse>

#include "bemcontact/contact/free_motions.hpp"
#include "bemcontact/contact/zone_ends.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/dd/interface.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::contact {

Vector CondensedProblem::jump_at(double t) const {
  Vector w = Vector::Zero(2 * pairs);
  for (const auto& load : loads) w += load.amplitude.at(t) * load.a;
  return w;
}

Vector CondensedProblem::target_at(double t) const {
  Vector target = force_at(t);
  for (const auto& load : loads) target -= load.amplitude.at(t) * load.F0;
  return target;
}

Vector CondensedProblem::force_at(double t) const {
  Vector out(motions);
  for (Index k = 0; k < motions; ++k) out[k] = force[k] == 0.0 ? 0.0 : force_amplitude[k].at(t) * force[k];
  return out;
}

Vector CondensedProblem::apply_M(const Vector& x) const {
  if (M_products) return M_products->apply(x).col(0);
  if (!matrix_free) {
    // Row blocks in parallel (memory-bound: two cores read M faster than one), from 512
    // rows: 8 blocks of whole SIMD packets, at least 256 rows each, fixed by the size alone
    // so that the product is the same whatever the thread count.
    const Index rows = M.rows();
    Vector y(rows);
    const Index block = std::max<Index>(256, ((rows / 8 + 7) / 8) * 8);
    const Index blocks = (rows + block - 1) / block;
#pragma omp parallel for schedule(static) if (rows >= 512)
    for (Index b = 0; b < blocks; ++b) {
      const Index first = b * block, count = std::min(block, rows - first);
      y.segment(first, count).noalias() = M.middleRows(first, count) * x;
    }
    return y;
  }
  Vector y;
  matrix_free->M->apply(x, y);
  return y;
}

bool CondensedProblem::half_model(Index first, Index last) const {
  if (half_models.empty()) return false;
  const auto all = pair_groups(*this);
  bool every = true;
  for (std::size_t c = 0; c + 1 < all.size(); ++c) {
    if (all[c] == first && all[c + 1] == last) return half_models[c];
    every = every && half_models[c];
  }
  return every;
}

void drop_tangential_coupling(CondensedProblem& problem) {
  for (Index i = 0; i < problem.pairs; ++i)
    for (Index j = 0; j < problem.pairs; ++j) problem.M(2 * i, 2 * j + 1) = 0.0;
}

// Types of the condensation's state (ContactModel::Build), named for the class's linkage.
namespace condensation {

// Where a region's variable dofs come from.
enum class BlockKind { side1, side2, platen };
struct Block {
  BlockKind kind = BlockKind::side1;
  std::size_t contact = 0;  // the contact, or the platen
  Index offset = 0;  // first variable dof of the block in the region
};

struct RegionVariables {
  std::vector<bem::VariableNode> nodes;
  std::vector<Block> blocks;
  Index bond_dofs = 0;
  std::vector<Index> bond_unknown;  // per bond dof: the body's bond unknown
};

// From a rigid body's centre of rotation to a point of its contact (the side-1 node it
// faces: the gap is small against the arm).
Vec2 rotation_arm(const ContactProblem& problem, int body, const Vec2& point) {
  return point - *problem.bodies.at(body).rigid->reference;
}

Index block_offset(const RegionVariables& variables, BlockKind kind, std::size_t contact) {
  for (const auto& block : variables.blocks)
    if (block.kind == kind && block.contact == contact) return block.offset;
  return -1;
}

}  // namespace condensation

using condensation::Block;
using condensation::BlockKind;
using condensation::RegionVariables;
using condensation::block_offset;
using condensation::rotation_arm;

// The state the phases of the condensation hand on to each other (docs/model.md, steps 2-6).
struct ContactModel::Build {
  Index n = 0;              // pairs
  Index force_motions = 0;  // motions that are force loads' approaches
  Index K = 0;              // motions
  Index nq = 0;             // contact unknowns q = (x, delta): 2n + K
  Index groups = 0;         // load groups of the bodies' own data
  std::vector<condensation::RegionVariables> variables;        // per region
  std::vector<dd::Connectivity> bonds;                          // per body
  std::vector<std::vector<bem::PointConstraint>> pins;          // per region: the free motions' pins
  std::vector<std::pair<int, Index>> pin_of_motion;             // per free motion: region, pin index
  std::vector<Matrix> flexibility, own_response;                // per region (factor_regions)
  std::vector<Eigen::SparseMatrix<double>> G;                   // per region (factor_regions): dofs x nq
  std::vector<Matrix> response, response0;                      // per region (form_affine_responses)
  std::vector<int> load_of_body;                                // per body: its rigid motion's load, or -1
  std::vector<char> keep_flexibility;                          // per region: kept for with_added_responses
  // M is applied through the regions, not formed (choose_condensed_operator): the responses
  // hold only the motions' columns, C_r G_r's last K.
  bool matrix_free = false;
  Index response_columns() const { return matrix_free ? K : nq; }
  // Whether region r forms its flexibility C_r (dofs^2): for its bonds' elimination or to
  // keep it; any other region solves for C_r G_r directly (form_affine_responses).
  bool forms_flexibility(std::size_t r) const { return variables[r].bond_dofs > 0 || keep_flexibility[r]; }
  // Per body (eliminate_bonds): its bond equations K U + L q + l0 = 0 (l0 per load group).
  struct BondEquations {
    Matrix K, L, l0;
  };
  std::vector<BondEquations> bond_equations;
  // Per region (assemble_motion_equations): the motions' equations per unit complementary
  // value at its variable nodes (a platen's weights, a pin's reaction), K x dofs.
  std::vector<Matrix> motion_rows;
};

// What with_added_responses takes from the condensation, for the bodies of elastoplastic
// regions (empty elsewhere).
struct ContactModel::KeptElimination {
  std::vector<Build::BondEquations> bond_equations;  // per body
  std::vector<Matrix> flexibility;                   // per region: C_r
  std::vector<Matrix> motion_rows;                   // per region
  std::vector<std::vector<Index>> bond_unknown;      // per region
};

ContactModel::~ContactModel() = default;

ContactModel::ContactModel(const ContactProblem& problem, const bem::ProgressCallback& progress)
    : problem_(problem), prepared_(prepare_contact(problem)) {
  Build build;
  // Kept for the bodies of elastoplastic regions only (a region's C_r is dofs^2).
  std::vector<bool> plastic_body(problem_.bodies.size(), false);
  for (const auto& region : prepared_.regions)
    if (region.definition.plasticity) plastic_body[region.body] = true;
  for (const auto& region : prepared_.regions) build.keep_flexibility.push_back(plastic_body[region.body] ? 1 : 0);
  number_pairs_and_motions(build);
  collect_region_variables(build);
  factor_regions(build, progress);
  choose_condensed_operator(build);
  eliminate_bonds(build);
  form_affine_responses(build);
  assemble_jumps_and_loads(build);
  assemble_motion_equations(build);
  if (build.matrix_free) form_matrix_free_operator(build);
  else compress_formed_operator(build);
  bond_dofs_.clear();
  for (const auto& v : build.variables) bond_dofs_.push_back(v.bond_dofs);
  pins_ = build.pins;
  if (std::find(plastic_body.begin(), plastic_body.end(), true) == plastic_body.end()) return;
  kept_ = std::make_unique<KeptElimination>();
  kept_->bond_equations.resize(problem_.bodies.size());
  kept_->flexibility.resize(prepared_.regions.size());
  kept_->motion_rows.resize(prepared_.regions.size());
  kept_->bond_unknown.resize(prepared_.regions.size());
  for (std::size_t b = 0; b < plastic_body.size(); ++b)
    if (plastic_body[b]) kept_->bond_equations[b] = std::move(build.bond_equations[b]);
  for (std::size_t r = 0; r < prepared_.regions.size(); ++r) {
    if (!plastic_body[prepared_.regions[r].body]) continue;
    kept_->flexibility[r] = std::move(build.flexibility[r]);
    kept_->motion_rows[r] = std::move(build.motion_rows[r]);
    kept_->bond_unknown[r] = std::move(build.variables[r].bond_unknown);
  }
}

// Step 2-3 of docs/model.md: the pairs of every contact one after the other, and the
// motions: the force loads' approaches first, then the free motions of bodies held only by
// their contacts (free_motions.hpp).
void ContactModel::number_pairs_and_motions(Build& build) {
  pair_offsets_.push_back(0);
  for (const auto& contact : prepared_.contacts) {
    pairs_.insert(pairs_.end(), contact.pairs.begin(), contact.pairs.end());
    pair_offsets_.push_back(static_cast<Index>(pairs_.size()));
  }
  build.n = static_cast<Index>(pairs_.size());  // 0 for bodies without contacts
  free_motions_ = contact::free_motions(problem_, prepared_, pairs_, pair_offsets_);
  build.force_motions = static_cast<Index>(problem_.forces.size());
  build.K = build.force_motions + static_cast<Index>(free_motions_.pins.size());
  build.nq = 2 * build.n + build.K;  // q = (x, delta): delta_k in column 2n + k
  // The bodies' own data by load group (0: data_amplitude; g: boundary_amplitudes[g - 1]).
  build.groups = static_cast<Index>(problem_.boundary_amplitudes.size()) + 1;
}

// Step 4's data: the variable nodes of every region (bond nodes, contact zone nodes, platen
// nodes) and the pins of the free motions.
void ContactModel::collect_region_variables(Build& build) {
  const auto& problem = problem_;
  const auto& regions = prepared_.regions;
  auto& variables = build.variables;
  auto& bonds = build.bonds;
  auto& pins = build.pins;
  auto& pin_of_motion = build.pin_of_motion;
  variables.assign(regions.size(), {});
  bonds.assign(problem.bodies.size(), {});
  pins.assign(regions.size(), {});
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const auto& members = prepared_.body_regions[b];
    if (members.size() < 2) continue;
    dd::DecompositionProblem decomposition;
    decomposition.part_word = "region";
    decomposition.analysis = problem.analysis;
    decomposition.mesh = problem.mesh;
    decomposition.options.method = dd::InterfaceMethod::conforming;
    std::vector<geometry::BoundaryMesh> meshes;
    for (std::size_t k = 0; k < members.size(); ++k) {
      dd::Subdomain sub = problem.bodies[b].regions[k];
      sub.body = regions[members[k]].definition;
      decomposition.subdomains.push_back(sub);
      meshes.push_back(regions[members[k]].mesh);
    }
    bonds[b] = dd::build_connectivity(decomposition, meshes);
    for (std::size_t k = 0; k < members.size(); ++k) {
      auto& v = variables[members[k]];
      v.nodes = bonds[b].variable_nodes[k];
      v.bond_dofs = 2 * static_cast<Index>(v.nodes.size());
      for (const auto& slot : bonds[b].slots[k])
        for (int j = 0; j < 2; ++j) v.bond_unknown.push_back(bonds[b].unknown_of(slot) + j);
    }
  }
  for (std::size_t c = 0; c < prepared_.contacts.size(); ++c) {
    const auto& contact = prepared_.contacts[c];
    auto& v1 = variables[contact.region1];
    v1.blocks.push_back({BlockKind::side1, c, 2 * static_cast<Index>(v1.nodes.size())});
    for (const auto& pair : contact.pairs) v1.nodes.push_back({pair.node1, bem::ConditionKind::traction});
    if (contact.region2 < 0) continue;
    auto& v2 = variables[contact.region2];
    v2.blocks.push_back({BlockKind::side2, c, 2 * static_cast<Index>(v2.nodes.size())});
    for (const Index node : contact.zone_nodes2) v2.nodes.push_back({node, bem::ConditionKind::traction});
  }
  for (std::size_t p = 0; p < prepared_.platens.size(); ++p) {
    auto& v = variables[prepared_.platens[p].region];
    v.blocks.push_back({BlockKind::platen, p, 2 * static_cast<Index>(v.nodes.size())});
    for (const Index node : prepared_.platens[p].nodes) v.nodes.push_back({node, bem::ConditionKind::displacement});
  }
  // Free motions: a variable point constraint each, its datum after the region's nodes.
  for (const auto& motion : free_motions_.pins) {
    pin_of_motion.emplace_back(motion.region, static_cast<Index>(pins[motion.region].size()));
    pins[motion.region].push_back(motion.constraint);
  }

}

// Step 4: every region factored once (bem::FactoredBody), its unit responses (the
// flexibility of its variable data), its own data's responses by load group, and its data
// from the contact unknowns before the bonds, G_r q.
void ContactModel::factor_regions(Build& build, const bem::ProgressCallback& progress) {
  const auto& problem = problem_;
  const auto& regions = prepared_.regions;
  const std::size_t region_count = regions.size();
  const Index n = build.n, nq = build.nq, force_motions = build.force_motions, groups = build.groups;
  const auto& variables = build.variables;
  const auto& pins = build.pins;
  const auto& pin_of_motion = build.pin_of_motion;
  auto& flexibility = build.flexibility;
  auto& G = build.G;
  auto& own_response = build.own_response;
  flexibility.assign(region_count, {});
  G.assign(region_count, {});
  own_response.assign(region_count, {});
  factored_.resize(region_count);
  for (std::size_t r = 0; r < region_count; ++r) {
    bem::ProgressCallback region_progress;
    if (progress)
      region_progress = [&, r](const std::string& phase, double fraction) {
        progress(regions[r].label + ": " + phase, fraction);
      };
    try {
      factored_[r] = std::make_unique<bem::FactoredBody>(regions[r].mesh, regions[r].definition, problem.analysis,
                                                         variables[r].nodes, region_progress, pins[r],
                                                         problem.operator_choice);
    } catch (const SolverError& error) {
      // The hint is for a singular region; a matrix that is not finite has another cause.
      if (std::string(error.what()).find("is singular") == std::string::npos) throw;
      throw SolverError(std::string(error.what()) + " In a contact problem each body must be held without its "
                        "contact zones (which carry tractions only): " + regions[r].label +
                            " is free to move; prescribe displacements on it, bond it to a held region, or press "
                            "it with a force load (a rigid platen).",
                        error.failure());
    }
    const Index dofs = factored_[r]->variable_dofs();
    if (build.forms_flexibility(r)) flexibility[r] = factored_[r]->unit_responses();
    own_response[r] = Matrix::Zero(dofs, groups);
    for (int g = 0; g < factored_[r]->load_groups(); ++g) own_response[r].col(g) = factored_[r]->group_complementary(g);
    // G_r's entries (repeated ones sum): pair frames, the transfer, platens' and pins' ones.
    std::vector<Eigen::Triplet<double>> entries;
    const auto add_block = [&entries](Index row, Index col, const Mat2& block) {
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          if (block(i, j) != 0.0) entries.emplace_back(row + i, col + j, block(i, j));
    };
    for (std::size_t m = 0; m < pin_of_motion.size(); ++m)
      if (pin_of_motion[m].first == static_cast<int>(r))
        entries.emplace_back(2 * static_cast<Index>(variables[r].nodes.size()) + pin_of_motion[m].second,
                             2 * n + force_motions + static_cast<Index>(m), 1.0);
    for (const auto& block : variables[r].blocks) {
      if (block.kind == BlockKind::platen) {
        // The platen moves by the approach of each force load on it, in its component.
        for (std::size_t k = 0; k < problem.forces.size(); ++k) {
          if (prepared_.platen_of_force[k] != static_cast<int>(block.contact)) continue;
          const auto& platen = prepared_.platens[block.contact];
          for (Index l = 0; l < static_cast<Index>(platen.nodes.size()); ++l)
            entries.emplace_back(block.offset + 2 * l + problem.forces[k].component, 2 * n + static_cast<Index>(k), 1.0);
        }
        continue;
      }
      const auto& contact = prepared_.contacts[block.contact];
      const Index first = pair_offsets_[block.contact];
      for (Index i = 0; i < static_cast<Index>(contact.pairs.size()); ++i) {
        const Mat2 Ri = pairs_[first + i].traction_frame();
        if (block.kind == BlockKind::side1) {
          add_block(block.offset + 2 * i, 2 * (first + i), Ri);
        } else {
          // Side 2 carries -T p (the consistent transfer of pairing.hpp).
          for (Index k = 0; k < static_cast<Index>(contact.zone_nodes2.size()); ++k)
            if (contact.transfer(k, i) != 0.0)
              add_block(block.offset + 2 * k, 2 * (first + i), -contact.transfer(k, i) * Ri);
        }
      }
    }
    G[r].resize(dofs, nq);
    G[r].setFromTriplets(entries.begin(), entries.end());
  }

}

// Step 4b: whether M is formed or applied through the regions (SolverOptions::contact_operator).
void ContactModel::choose_condensed_operator(Build& build) {
  const auto& solver = problem_.solver;
  if (solver.contact_operator == CondensedOperatorKind::dense) return;
  std::string obstacle = matrix_free_obstacle(problem_);
  if (obstacle.empty() && !build.pin_of_motion.empty())
    obstacle = "a body is held only by its contacts (its equilibrium is a row of the formed operator)";
  if (solver.contact_operator == CondensedOperatorKind::matrix_free) {
    if (!obstacle.empty())
      throw InputError(solver.contact_operator_where, "the condensed operator cannot be applied matrix-free: " +
                                                          obstacle + " (remove contact_operator, or set it to \"dense\")");
    build.matrix_free = true;
    return;
  }
  const bool compressed = std::all_of(factored_.begin(), factored_.end(), [](const auto& f) { return f->compressed(); });
  build.matrix_free = obstacle.empty() && compressed && build.n >= SolverOptions::matrix_free_threshold;
}

namespace {

// Of M's products in a long history (the 961-pair fretting cycle: 1 698 iterations, each
// one product): the dense product reads M whole, 2N x 2N, which leaves the caches from about
// 1 000 pairs; the compressed M is 0.38 / 0.24 / 0.15 of it at 481 / 961 / 1 921 pairs, its
// products within 3e-15 of M's. At 1e-12 (2.6 / 9 / 7 times faster than M's on one thread)
// the error, 1e-12 at 1 921 pairs, put the residual of 1 195 of that cycle's 2 106 steps above
// the tolerance 1e-10: one iteration more each (4 619 against M's 3 320); at 1e-14 the cycle
// takes M's 3 320, 108 -> 94 s on 2 threads (M's own products: 106 s).
constexpr double kProductAccuracy = 1e-14;

}  // namespace

// Step 6 (docs/model.md), on the formed route chosen automatically from
// compressed_products_threshold pairs: M also as a hierarchical matrix over the pairs'
// positions (ACA+ one component's rows at a time), for the products of the iterations. Checked
// once against M on a fixed vector: beyond 100 times the accuracy asked the products stay M's.
void ContactModel::compress_formed_operator(const Build& build) {
  auto& cp = condensed_;
  if (problem_.solver.contact_operator != CondensedOperatorKind::automatic || cp.M.size() == 0 ||
      build.n < SolverOptions::compressed_products_threshold || !operators::hmatrix_available())
    return;
  std::vector<Vec2> points;
  operators::HMatrixOptions options = operators::HMatrixOptions::with_accuracy(kProductAccuracy);
  for (Index i = 0; i < build.n; ++i)
    for (int component = 0; component < 2; ++component) {
      points.push_back(pairs_[static_cast<std::size_t>(i)].position1);
      options.row_component.push_back(component);
    }
  const Matrix& M = cp.M;
  auto compressed = std::make_shared<const operators::HMatrix>(
      points, points,
      [&M](const std::vector<Index>& rows, const std::vector<Index>& cols, double* out) {
        for (std::size_t j = 0; j < cols.size(); ++j)
          for (std::size_t i = 0; i < rows.size(); ++i) out[i + j * rows.size()] = M(rows[i], cols[j]);
      },
      options, "the condensed operator");
  Vector probe(M.cols());
  for (Index k = 0; k < probe.size(); ++k) probe[k] = 1.0 + 0.5 * std::sin(1.7 * static_cast<double>(k));
  const Vector exact = M * probe;
  if ((compressed->apply(probe).col(0) - exact).norm() <= 100.0 * kProductAccuracy * exact.norm())
    cp.M_products = std::move(compressed);
}

namespace condensation {

// M x = sum_r J_r C_r G_r x (docs/model.md, step 6 without forming M): one solve of each
// region's factors per product, only the pairs' columns of G_r (x holds no motions).
class RegionsCondensedOperator : public CondensedOperator {
 public:
  RegionsCondensedOperator(const std::vector<std::unique_ptr<bem::FactoredBody>>& regions,
                           const std::vector<Eigen::SparseMatrix<double>>& data_map,
                           const std::vector<Eigen::SparseMatrix<double>>& jump_map, Index pairs)
      : regions_(regions), data_map_(data_map), jump_map_(jump_map), n_(pairs) {}
  Index rows() const override { return 2 * n_; }
  Index cols() const override { return 2 * n_; }
  void apply(const Vector& x, Vector& y) const override {
    y = Vector::Zero(2 * n_);
    for (std::size_t r = 0; r < regions_.size(); ++r) {
      const Vector data = data_map_[r].leftCols(2 * n_) * x;
      if (data.isZero(0.0)) continue;
      y += jump_map_[r] * regions_[r]->complementary(data, false);
    }
  }
  Matrix apply_columns(const Eigen::SparseMatrix<double>& X) const override {
    Matrix Y = Matrix::Zero(2 * n_, X.cols());
    for (std::size_t r = 0; r < regions_.size(); ++r) {
      const Eigen::SparseMatrix<double> data = data_map_[r].leftCols(2 * n_) * X;
      if (data.nonZeros() == 0) continue;
      Y += jump_map_[r] * regions_[r]->complementary_columns(data);
    }
    return Y;
  }

 private:
  const std::vector<std::unique_ptr<bem::FactoredBody>>& regions_;
  const std::vector<Eigen::SparseMatrix<double>>& data_map_;
  const std::vector<Eigen::SparseMatrix<double>>& jump_map_;
  Index n_;
};

}  // namespace condensation

// Step 6b of the matrix-free route: M as an operator on the factored regions, with the
// coarse space of its step solver's preconditioner.
void ContactModel::form_matrix_free_operator(Build& build) {
  auto op = std::make_shared<condensation::RegionsCondensedOperator>(factored_, contact_data_map_, jump_map_, build.n);
  Vector weight(build.n);
  for (Index g = 0; g < build.n; ++g) weight[g] = pairs_[g].weight;
  const bool friction = std::any_of(problem_.contacts.begin(), problem_.contacts.end(),
                                    [](const auto& contact) { return contact.law.friction > 0.0; });
  condensed_.matrix_free = std::make_shared<const MatrixFreeCondensed>(
      prepare_matrix_free(std::move(op), std::move(weight), pair_groups(condensed_), friction));
}

// Step 5: each body's bond unknowns eliminated by one dense solve of the bonds' nodal
// equilibrium K U + L q + l0 = 0 (the conforming method's Schur complement): every region's
// data becomes an affine function of the contact unknowns, D_r q + d0_r.
void ContactModel::eliminate_bonds(Build& build) {
  const auto& problem = problem_;
  const std::size_t region_count = prepared_.regions.size();
  const Index nq = build.nq, groups = build.groups;
  const auto& variables = build.variables;
  const auto& bonds = build.bonds;
  const auto& flexibility = build.flexibility;
  const auto& own_response = build.own_response;
  // D_r is G_r (moved: it is not needed apart; zero in the bond rows) below its bond rows,
  // which the elimination fills.
  contact_data_map_ = std::move(build.G);
  const auto& G = contact_data_map_;
  bond_data_map_.assign(region_count, Matrix());
  data_offset_.assign(region_count, Matrix());
  for (std::size_t r = 0; r < region_count; ++r) {
    bond_data_map_[r] = Matrix::Zero(variables[r].bond_dofs, nq);
    data_offset_[r] = Matrix::Zero(G[r].rows(), groups);
  }
  build.bond_equations.assign(problem.bodies.size(), {});
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const Index nb = bonds[b].unknowns;
    if (nb == 0) continue;
    Matrix& K = build.bond_equations[b].K;
    Matrix& L = build.bond_equations[b].L;
    Matrix& l0 = build.bond_equations[b].l0;
    K = Matrix::Zero(nb, nb), L = Matrix::Zero(nb, nq), l0 = Matrix::Zero(nb, groups);
    for (const int r : prepared_.body_regions[b]) {
      const auto& v = variables[r];
      const Matrix bond_rows = flexibility[r].topRows(v.bond_dofs);
      const Matrix bond_rows_G = bond_rows * G[r];
      for (Index i = 0; i < v.bond_dofs; ++i) {
        for (Index j = 0; j < v.bond_dofs; ++j) K(v.bond_unknown[i], v.bond_unknown[j]) += bond_rows(i, j);
        L.row(v.bond_unknown[i]) += bond_rows_G.row(i);
        l0.row(v.bond_unknown[i]) += own_response[r].row(i);
      }
    }
    // A bond node on the axis of an axisymmetric body keeps u_r = 0 (its radial datum and
    // traction are fixed by symmetry): its unknown appears in no equation.
    for (Index i = 0; i < nb; ++i)
      if (K.row(i).cwiseAbs().maxCoeff() == 0.0 && K.col(i).cwiseAbs().maxCoeff() == 0.0) K(i, i) = 1.0;
    std::unique_ptr<operators::DenseLU> lu;
    try {
      lu = std::make_unique<operators::DenseLU>(K, "the bond equations of body '" + problem.bodies[b].name + "'");
    } catch (const SolverError& error) {
      throw SolverError(std::string(error.what()) + ": body '" + problem.bodies[b].name +
                            "' is free to move as a whole; prescribe displacements on one of its regions or press "
                            "it with a force load.",
                        error.failure());
    }
    Matrix Uq = -L;
    lu->solve_in_place(Uq);
    Matrix U0 = -l0;
    lu->solve_in_place(U0);
    for (const int r : prepared_.body_regions[b]) {
      const auto& v = variables[r];
      for (Index i = 0; i < v.bond_dofs; ++i) {
        bond_data_map_[r].row(i) = Uq.row(v.bond_unknown[i]);
        data_offset_[r].row(i) = U0.row(v.bond_unknown[i]);
      }
    }
  }

}

// Step 5's result: each region's complementary field at its variable nodes as an affine
// map of q, C_r (D_r q + d0_r) + c0_r.
void ContactModel::form_affine_responses(Build& build) {
  const std::size_t region_count = prepared_.regions.size();
  auto& flexibility = build.flexibility;
  const auto& own_response = build.own_response;
  auto& response = build.response;
  auto& response0 = build.response0;
  response.assign(region_count, {});
  response0.assign(region_count, {});
  for (std::size_t r = 0; r < region_count; ++r) {
    if (!build.forms_flexibility(r)) {
      // No bonds: D_r = G_r, d0_r = 0, and C_r G_r is solved for column by column (only the
      // motions' on the matrix-free route).
      const Index columns = build.response_columns();
      response[r] = factored_[r]->complementary_columns(
          Eigen::SparseMatrix<double>(contact_data_map_[r].rightCols(columns)));
      response0[r] = own_response[r];
      continue;
    }
    // Below the bond rows the data map is 2x2 pair frames and the transfer's few entries: a
    // sparse product, O(dofs x nonzeros) instead of O(dofs^2 x nq).
    response[r] = flexibility[r] * contact_data_map_[r];
    if (bond_data_map_[r].rows() > 0) response[r] += flexibility[r].leftCols(bond_data_map_[r].rows()) * bond_data_map_[r];
    response0[r] = flexibility[r] * data_offset_[r] + own_response[r];
    if (!build.keep_flexibility[r]) flexibility[r] = Matrix();  // dofs^2: freed before the jumps
  }

}

// Step 6: the jumps w = w0(t) + M x + b delta of every pair in its frame, with the loads
// (the bodies' own data by group, interferences, rigid bodies' prescribed motions) and the
// gaps.
void ContactModel::assemble_jumps_and_loads(Build& build) {
  const auto& problem = problem_;
  const auto& regions = prepared_.regions;
  const Index n = build.n, K = build.K, groups = build.groups;
  const auto& variables = build.variables;
  const auto& response = build.response;
  const auto& response0 = build.response0;
  // Jumps w = Q (u1 - u2) per pair; loads: the bodies' own data (load 0), then each rigid
  // body's prescribed translation.
  auto& cp = condensed_;
  cp.pairs = n;
  // The responses' columns: the pairs' (unless matrix-free), then the motions'.
  const Index x_columns = build.response_columns() - K;
  if (x_columns > 0) cp.M = Matrix::Zero(2 * n, 2 * n);
  cp.b = Matrix::Zero(2 * n, K);
  std::vector<std::vector<Eigen::Triplet<double>>> jump_entries(regions.size());
  const auto add_jump = [&](int r, Index row, Index col, const Mat2& block) {
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        if (block(i, j) != 0.0) jump_entries[static_cast<std::size_t>(r)].emplace_back(row + i, col + j, block(i, j));
  };
  cp.loads.push_back({problem.data_amplitude, Vector::Zero(2 * n), Vector::Zero(K)});
  for (const auto& amplitude : problem.boundary_amplitudes) cp.loads.push_back({amplitude, Vector::Zero(2 * n), Vector::Zero(K)});
  // Interferences: the overlap d - interference of each pair, as a jump +interference along
  // the normal that follows the contact's amplitude.
  for (std::size_t c = 0; c < prepared_.contacts.size(); ++c) {
    if (problem.contacts[c].interference == 0.0) continue;
    CondensedLoad load{problem.contacts[c].interference_amplitude, Vector::Zero(2 * n), Vector::Zero(K)};
    for (Index g = pair_offsets_[c]; g < pair_offsets_[c + 1]; ++g) load.a[2 * g] = pairs_[g].interference;
    cp.loads.push_back(load);
  }
  auto& load_of_body = build.load_of_body;
  load_of_body.assign(problem.bodies.size(), -1);
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const auto& rigid = problem.bodies[b].rigid;
    if (!rigid || (!rigid->displacement && !rigid->rotation)) continue;
    load_of_body[b] = static_cast<int>(cp.loads.size());
    cp.loads.push_back({rigid->amplitude, Vector::Zero(2 * n), Vector::Zero(K)});
  }
  for (std::size_t c = 0; c < prepared_.contacts.size(); ++c) {
    const auto& contact = prepared_.contacts[c];
    const Index first = pair_offsets_[c];
    const Index o1 = block_offset(variables[contact.region1], BlockKind::side1, c);
    const Index o2 = contact.region2 >= 0 ? block_offset(variables[contact.region2], BlockKind::side2, c) : -1;
    for (Index i = 0; i < static_cast<Index>(contact.pairs.size()); ++i) {
      const auto& pair = contact.pairs[i];
      const Mat2 Qg = pairs_[first + i].frame();
      Matrix u = response[contact.region1].middleRows(o1 + 2 * i, 2);
      Matrix u0 = response0[contact.region1].middleRows(o1 + 2 * i, 2);  // 2 x groups
      const Index row = 2 * (first + i);
      add_jump(contact.region1, row, o1 + 2 * i, Qg);
      if (contact.mortar.size() > 0) {
        // The weighted jump (pairing.hpp, mortar).
        for (Index a = 0; a < contact.mortar.rows(); ++a) {
          const double c = contact.mortar(a, i);
          if (c == 0.0) continue;
          u -= c * response[contact.region2].middleRows(o2 + 2 * a, 2);
          u0 -= c * response0[contact.region2].middleRows(o2 + 2 * a, 2);
          add_jump(contact.region2, row, o2 + 2 * a, -c * Qg);
        }
      } else if (contact.region2 >= 0) {
        for (int a = 0; a < pair.count2; ++a) {
          u -= pair.shape2[a] * response[contact.region2].middleRows(o2 + 2 * pair.zone2[a], 2);
          u0 -= pair.shape2[a] * response0[contact.region2].middleRows(o2 + 2 * pair.zone2[a], 2);
          add_jump(contact.region2, row, o2 + 2 * pair.zone2[a], -pair.shape2[a] * Qg);
        }
      } else {
        // The rigid body translates by its force loads' approaches and its prescribed displacement.
        for (std::size_t k = 0; k < problem.forces.size(); ++k) {
          if (problem.forces[k].body != contact.rigid_body) continue;
          const Index column = x_columns + static_cast<Index>(k);
          if (problem.forces[k].component < 2) {
            u(problem.forces[k].component, column) -= 1.0;
          } else {  // a small rotation theta about the reference: theta (-arm_y, arm_x)
            const Vec2 arm = rotation_arm(problem, contact.rigid_body, pair.position1);
            u(0, column) += arm.y();
            u(1, column) -= arm.x();
          }
        }
        if (load_of_body[contact.rigid_body] >= 0) {
          const auto& rigid = *problem.bodies[contact.rigid_body].rigid;
          Vec2 motion = rigid.displacement.value_or(Vec2::Zero());
          if (rigid.rotation) {
            const Vec2 arm = rotation_arm(problem, contact.rigid_body, pair.position1);
            motion += *rigid.rotation * Vec2(-arm.y(), arm.x());
          }
          cp.loads[load_of_body[contact.rigid_body]].a.segment<2>(2 * (first + i)) = -Qg * motion;
        }
      }
      const Matrix w = Qg * u;
      if (x_columns > 0) cp.M.middleRows(2 * (first + i), 2) = w.leftCols(2 * n);
      cp.b.middleRows(2 * (first + i), 2) = w.rightCols(K);
      const Matrix w0 = Qg * u0;
      for (Index g = 0; g < groups; ++g) cp.loads[g].a.segment<2>(2 * (first + i)) = w0.col(g);
    }
  }
  jump_map_.assign(regions.size(), {});
  for (std::size_t r = 0; r < regions.size(); ++r) {
    jump_map_[r].resize(2 * n, response[r].rows());
    jump_map_[r].setFromTriplets(jump_entries[r].begin(), jump_entries[r].end());  // sums repeated entries
  }
  // (Matrix-free: frictionless, tau = 0, so the normal jumps take nothing from it anyway.)
  if (!problem.tangential_coupling && x_columns > 0) drop_tangential_coupling(cp);
  cp.gap.resize(n);
  cp.on_axis.resize(n);
  for (Index g = 0; g < n; ++g) {
    cp.gap[g] = pairs_[g].gap;
    cp.on_axis[g] = pairs_[g].on_axis;
  }
  cp.groups = pair_offsets_;
  for (const auto& contact : prepared_.contacts)
    cp.half_models.push_back(zone_starts_on_symmetry_line(problem, contact, prepared_.regions));
  for (const auto& region : regions) cp.length_scale = std::max(cp.length_scale, region.mesh.scale);
  cp.motions = K;
}

// Step 6: the motions' equations f x + f_delta delta = force(t) - F0(t): each force load's
// platen or rigid body in equilibrium with its force, each free motion's pin without
// reaction.
void ContactModel::assemble_motion_equations(Build& build) {
  const auto& problem = problem_;
  const Index n = build.n, nq = build.nq, K = build.K, force_motions = build.force_motions, groups = build.groups;
  const auto& variables = build.variables;
  const auto& pin_of_motion = build.pin_of_motion;
  const auto& response = build.response;
  const auto& response0 = build.response0;
  auto& cp = condensed_;
  Matrix F = Matrix::Zero(K, nq);
  Matrix F0 = Matrix::Zero(K, groups);
  auto& motion_rows = build.motion_rows;
  motion_rows.assign(prepared_.regions.size(), Matrix());
  for (std::size_t r = 0; r < motion_rows.size(); ++r) motion_rows[r] = Matrix::Zero(K, response[r].rows());
  cp.force = Vector::Zero(K);
  cp.force_amplitude.assign(K, Amplitude{});
  for (std::size_t k = 0; k < problem.forces.size(); ++k) {
    const auto& load = problem.forces[k];
    const Index row = static_cast<Index>(k);
    cp.force[row] = load.force;
    cp.force_amplitude[k] = load.amplitude;
    const int p = prepared_.platen_of_force[k];
    if (p < 0) {
      // The force on a rigid body is the integral of the traction its contacts apply to side 1.
      for (std::size_t c = 0; c < prepared_.contacts.size(); ++c) {
        if (prepared_.contacts[c].rigid_body != load.body) continue;
        for (Index g = pair_offsets_[c]; g < pair_offsets_[c + 1]; ++g) {
          if (load.component < 2) {
            F.block<1, 2>(row, 2 * g) = pairs_[g].weight * pairs_[g].traction_frame().row(load.component);
          } else {  // the moment of the traction about the reference: arm_x t_y - arm_y t_x
            const Vec2 arm = rotation_arm(problem, load.body, pairs_[g].position1);
            F.block<1, 2>(row, 2 * g) = pairs_[g].weight * (arm.x() * pairs_[g].traction_frame().row(1) - arm.y() * pairs_[g].traction_frame().row(0));
          }
        }
      }
      continue;
    }
    const auto& platen = prepared_.platens[p];
    const Index of = block_offset(variables[platen.region], BlockKind::platen, static_cast<std::size_t>(p));
    for (Index l = 0; l < static_cast<Index>(platen.nodes.size()); ++l)
      motion_rows[platen.region](row, of + 2 * l + load.component) += platen.weights[l];
  }
  // A free motion's equation: its pin's reaction vanishes (the body's equilibrium).
  for (std::size_t m = 0; m < pin_of_motion.size(); ++m) {
    const auto [r, q] = pin_of_motion[m];
    motion_rows[r](force_motions + static_cast<Index>(m), 2 * static_cast<Index>(variables[r].nodes.size()) + q) = 1.0;
  }
  for (std::size_t r = 0; r < motion_rows.size(); ++r) {
    if (motion_rows[r].isZero(0.0)) continue;
    F.rightCols(response[r].cols()) += motion_rows[r] * response[r];
    F0 += motion_rows[r] * response0[r];
  }
  for (Index g = 0; g < groups; ++g) cp.loads[g].F0 = F0.col(g);
  cp.f = F.leftCols(2 * n);
  cp.f_delta = F.rightCols(K);
}

ResponseChange ContactModel::with_added_responses(const std::vector<AddedResponse>& added, double t) const {
  if (!kept_) throw std::logic_error("with_added_responses: no elastoplastic region in the model");
  const Index n = condensed_.pairs;
  const auto amplitudes = problem_.group_amplitudes(t);
  const Vector a = Eigen::Map<const Vector>(amplitudes.data(), static_cast<Index>(amplitudes.size()));
  const auto& regions = prepared_.regions;
  ResponseChange change;
  const Index K = condensed_.motions;
  change.jumps = Matrix::Zero(2 * n, 2 * n + K);
  change.jump = Vector::Zero(2 * n);
  change.motions = Matrix::Zero(K, 2 * n + K);
  change.motion_offset = Vector::Zero(K);
  change.changed.assign(regions.size(), 0);
  change.data_map.resize(regions.size());
  change.data_offset.resize(regions.size());
  std::vector<const AddedResponse*> added_of(regions.size(), nullptr);
  for (const auto& response : added) added_of.at(static_cast<std::size_t>(response.region)) = &response;
  for (std::size_t b = 0; b < problem_.bodies.size(); ++b) {
    const auto& members = prepared_.body_regions[b];
    if (std::none_of(members.begin(), members.end(), [&](int r) { return added_of[r] != nullptr; })) continue;
    // K' U = -(L' q + l0') with each added region's bond rows (S_r: its dofs' bond unknowns):
    // K' = K + S^T F_bb S, L' = L + S^T F_b. G, l0' = l0 a + S^T u0_b.
    const auto& equations = kept_->bond_equations[b];
    const Index nb = equations.K.rows();
    Matrix Uq, U0;
    if (nb > 0) {
      Matrix K = equations.K, L = equations.L;
      Vector l0 = equations.l0 * a;
      for (const int r : members) {
        if (!added_of[r]) continue;
        const Matrix& F = *added_of[r]->flexibility;
        const Vector& u0 = *added_of[r]->offset;
        const auto& unknown = kept_->bond_unknown[r];
        const Index bond = bond_dofs_[r];
        // The data before the bonds, G_r (its bond rows are 0).
        const Matrix FG = F.topRows(bond) * contact_data_map_[r];
        for (Index i = 0; i < bond; ++i) {
          for (Index j = 0; j < bond; ++j) K(unknown[i], unknown[j]) += F(i, j);
          L.row(unknown[i]) += FG.row(i);
          l0[unknown[i]] += u0[i];
        }
      }
      const operators::DenseLU lu(std::move(K), "the bond equations of body '" + problem_.bodies[b].name +
                                                    "' with its elastoplastic regions' cells");
      Uq = -L;
      lu.solve_in_place(Uq);
      U0 = -l0;
      lu.solve_in_place(U0);
    }
    // Each region's data D'_r q + d0'_r, and the change of its complementary values
    //   (C_r + F_r)(D'_r q + d0'_r) + u0_r - C_r (D_r q + d0_r a),
    // through the jumps' map J_r and the motions' rows P_r.
    for (const int r : members) {
      const auto& unknown = kept_->bond_unknown[r];
      const Index bond = bond_dofs_[r];
      Matrix D = Matrix(contact_data_map_[r]);  // its rows past the bonds' are G_r's, unchanged
      Vector d0 = Vector::Zero(D.rows());
      for (Index i = 0; i < bond; ++i) D.row(i) = Uq.row(unknown[i]), d0[i] = U0(unknown[i], 0);
      const Matrix& C = kept_->flexibility[r];
      const Matrix dD = D.topRows(bond) - bond_data_map_[r];
      const Vector dd0 = d0.head(bond) - data_offset_[r].topRows(bond) * a;
      Matrix response = C.leftCols(bond) * dD;
      Vector offset = C.leftCols(bond) * dd0;
      if (const AddedResponse* plastic = added_of[r]) {
        response += *plastic->flexibility * D;
        offset += *plastic->flexibility * d0 + *plastic->offset;
      }
      change.jumps += jump_map_[r] * response;
      change.jump += jump_map_[r] * offset;
      if (!kept_->motion_rows[r].isZero(0.0)) {
        change.motions += kept_->motion_rows[r] * response;
        change.motion_offset += kept_->motion_rows[r] * offset;
      }
      change.changed[r] = 1;
      change.data_map[r] = std::move(D);
      change.data_offset[r] = std::move(d0);
    }
  }
  return change;
}

void ResponseChange::apply(const CondensedProblem& problem, CondensedProblem& changed_problem, Vector& jump0,
                           Vector& target) const {
  const Index n = problem.pairs;
  changed_problem.M = problem.M + jumps.leftCols(2 * n);
  changed_problem.M_products.reset();  // of the unchanged M
  changed_problem.b = problem.b + jumps.rightCols(problem.motions);
  changed_problem.f = problem.f + motions.leftCols(2 * n);
  changed_problem.f_delta = problem.f_delta + motions.rightCols(problem.motions);
  jump0 += jump;
  target -= motion_offset;
}

Vec2 ContactModel::traction(Index pair, const Vector& x) const {
  const auto& p = pairs_[pair];
  return -x[2 * pair] * p.normal + x[2 * pair + 1] * p.tangent;
}

bem::BoundarySolution ContactModel::region_solution(int r, const Vector& x, const Vector& delta, double t) const {
  Vector q(x.size() + delta.size());
  q << x, delta;
  const auto amplitudes = problem_.group_amplitudes(t);
  const Vector scale = Eigen::Map<const Vector>(amplitudes.data(), static_cast<Index>(amplitudes.size()));
  Vector data = contact_data_map_[r] * q + data_offset_[r] * scale;
  const Index bond = bond_data_map_[r].rows();
  if (bond > 0) data.head(bond) += bond_data_map_[r] * q;
  return factored_[r]->solve_with_amplitudes(data, amplitudes);
}

}  // namespace bemcontact::contact
