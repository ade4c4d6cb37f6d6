#pragma once
// A body made of several subdomains (materials) glued along shared interfaces: the
// problem the domain decomposition of chapters III-IV solves. Built by
// io/decomposition_file (or by code: tests, reference cases, benchmarks).
//
// Each subdomain is a one-body definition whose boundary pieces are either outer pieces
// with their own conditions or interface pieces, named: the two subdomains that share an
// interface both list a piece (or a chain of pieces) with that interface name, each
// traversed with its own domain on the left, so in opposite directions. Interface pieces
// carry the condition signature "interface:<name>", so the mesher splits the node where
// an interface meets anything else.
#include <string>
#include <vector>

#include "bemcontact/bem/problem.hpp"

namespace bemcontact::dd {

// Which continuity the interface unknowns carry (section IV.3).
enum class InterfaceMethod {
  conforming,  // displacements on the interface, equilibrium iterated: (IV.4), B = sum S
  hybrid,      // tractions on the interface, compatibility iterated: (IV.5), B' = sum S^-1
  mixed,       // the thesis' Hennizel variant: displacements on gamma_d, tractions on gamma_c (IV.6)
};
const char* to_string(InterfaceMethod method);

// How the interface iteration is preconditioned.
enum class InterfacePreconditioner {
  none,       // plain GMRES on K (the thesis' Alg IV.4)
  balancing,  // balancing Neumann-Neumann with a rigid-mode coarse space (conforming only)
};
const char* to_string(InterfacePreconditioner preconditioner);

struct Subdomain {
  bem::BodyDefinition body;                    // name, material, pieces, conditions, constraints
  std::vector<std::string> piece_interface;    // per piece: interface name, "" for outer pieces
  std::vector<bem::InteriorPoint> interior_points;
};

struct DecompositionOptions {
  // Conforming unknowns with the balancing preconditioner: iterations nearly independent of
  // the number of subdomains and of the materials' contrast (the thesis' mixed variant, the
  // fastest unpreconditioned method on its strips, needs 8x more on 64 strips).
  InterfaceMethod method = InterfaceMethod::conforming;
  InterfacePreconditioner preconditioner = InterfacePreconditioner::balancing;
  // GMRES(m). 0 (the default): no restart, m = max_iterations, when the Krylov basis
  // (m vectors of the interface size) fits in kAutoRestartBytes, else the largest m that
  // fits. Short restarts stall on stiff interfaces (a thin soft layer between stiff parts:
  // GMRES(20) left 1.8e-2 after 500 iterations where full GMRES converged in 100).
  int restart = 0;
  double tolerance = 1e-8;          // on ||r|| / ||r_00|| (Alg IV.4; thesis 1e-8)
  int max_iterations = 500;         // operator applications over all restarts
  // Facing nodes of an interface must coincide within this fraction of the geometry size.
  double interface_tolerance = 1e-6;
  // Mixed method: per interface, this many nodes spread evenly along it carry displacement
  // continuity (gamma_d); the others carry traction continuity (gamma_c). Two fix the rigid
  // motion of a floating subdomain; 3 converged fastest on the strips of IV.5.
  int displacement_nodes = 3;
  // false: K applied matrix-free, one subdomain solve per application (Alg IV.1).
  // true (always with the balancing preconditioner, which needs the maps): each subdomain's interface map (S, S^-1 or mixed) is formed once by a block solve
  // with unit data (one BLAS-3 solve), then K costs small dense products: worth it when
  // GMRES needs more iterations than a subdomain has interface unknowns.
  bool explicit_operators = false;

  // The method with its natural preconditioner: balancing for conforming, none otherwise.
  void set_method(InterfaceMethod m) {
    method = m;
    preconditioner = m == InterfaceMethod::conforming ? InterfacePreconditioner::balancing : InterfacePreconditioner::none;
  }
};

inline constexpr double kAutoRestartBytes = 256e6;
// The restart length used for `options` on an interface of `unknowns` unknowns.
int effective_restart(const DecompositionOptions& options, Index unknowns);

struct DecompositionProblem : bem::ProblemHeader {
  std::vector<Subdomain> subdomains;
  DecompositionOptions options;
  std::string part_word = "subdomain";  // in messages: "region" when they are a body's regions
};

// Marks piece `piece` of `subdomain` as part of interface `name` (no condition of its own).
void mark_interface(Subdomain& subdomain, std::size_t piece, const std::string& name);

// The one-body problem of subdomain s (its pieces, material, constraints, interior points),
// for meshing and for the writers.
bem::ProblemDefinition subdomain_problem(const DecompositionProblem& problem, std::size_t s);

}  // namespace bemcontact::dd
