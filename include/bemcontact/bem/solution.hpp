#pragma once
// Results of a one-body solve: what the writers in io/ take.
#include <array>
#include <chrono>
#include <string>
#include <vector>

#include "bemcontact/core/types.hpp"

namespace bemcontact::bem {

// In-plane components (x1, x2) = (x, y) or (r, z), plus the out-of-plane normal stress
// s33 (sigma_zz in plane strain, 0 in plane stress, sigma_theta_theta in axisymmetry).
struct StressTensor {
  double s11 = 0.0, s22 = 0.0, s12 = 0.0, s33 = 0.0;
  // Hencky-von Mises equivalent stress (section II.6).
  double von_mises() const;
  // The three principal stresses, largest first: the in-plane pair and s33 (the
  // out-of-plane direction is principal in plane and axisymmetric states).
  std::array<double, 3> principal() const;
};

// Resultant of the tractions on one boundary (bem/resultants.hpp).
struct BoundaryResultant {
  std::string boundary;
  bool prescribed_displacement = false;  // some component of u is prescribed there: a reaction
  // Plane problems: force per unit thickness, and its moment about the origin
  // (counterclockwise positive). Axisymmetry: the force on the whole surface of
  // revolution (2 pi r dGamma); its radial component vanishes by symmetry and is 0, and
  // there is no moment (0).
  Vec2 force = Vec2::Zero();
  double moment = 0.0;
};

struct BoundarySolution {
  std::vector<Vec2> displacement;  // per node, global components
  std::vector<Vec2> traction;      // per node, global components (p = sigma n)
  std::vector<StressTensor> stress;
  std::vector<BoundaryResultant> resultants;  // per boundary, with the stresses
};

struct InteriorSolution {
  std::vector<Vec2> points;
  std::vector<Vec2> displacement;
  std::vector<StressTensor> stress;
  std::vector<Vec2> dropped_points;  // grid points outside the body
  // Per point, its column and row in the [interior] grid ({-1, -1}: a listed point), so
  // that writers can draw the grid's cells (io/results_writer.hpp).
  std::vector<std::array<int, 2>> grid_index;
};

// Wall-clock time of each phase, in seconds, in the order run.
struct PhaseTimings {
  std::vector<std::pair<std::string, double>> phases;
  void add(const std::string& name, double seconds) { phases.emplace_back(name, seconds); }
  double total() const {
    double sum = 0.0;
    for (const auto& phase : phases) sum += phase.second;
    return sum;
  }
};

// Adds each phase's time to a PhaseTimings as it ends (lap: the time since the last lap).
class PhaseClock {
 public:
  explicit PhaseClock(PhaseTimings& timings) : timings_(timings) {}
  void lap(const std::string& phase) {
    const auto now = std::chrono::steady_clock::now();
    timings_.add(phase, std::chrono::duration<double>(now - start_).count());
    start_ = now;
  }

 private:
  PhaseTimings& timings_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

struct SolveReport {
  Index unknowns = 0;
  double reciprocal_condition = 0.0;  // LAPACK estimate of 1/cond_1(A); NaN: not estimated (H-LU)
  std::string operator_kind = "dense";  // "dense" or "compressed"
  double compression_ratio = 1.0;       // stored values / dense values (compressed)
  double compression_accuracy = 0.0;    // the accuracy it was built to (compressed)
  double relative_residual = 0.0;     // ||H u - G p|| / ||G p||
  // Point constraints only fixed rigid modes: no reactions, and the residual is the
  // imbalance of the discretised loads.
  bool constraints_fix_rigid_modes_only = false;
  int threads = 1;
};

}  // namespace bemcontact::bem
