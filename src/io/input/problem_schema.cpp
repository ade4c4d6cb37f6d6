#include "bemcontact/io/input/problem_schema.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "bemcontact/io/text_format.hpp"

namespace bemcontact::io::schema {

bool Range::contains(double value) const {
  if (min && !(min_open ? value > *min : value >= *min)) return false;
  if (max && !(max_open ? value < *max : value <= *max)) return false;
  return true;
}

std::string Range::text() const {
  if (min && max)
    return std::string("in ") + (min_open ? "(" : "[") + format_number(*min) + ", " + format_number(*max) +
           (max_open ? ")" : "]");
  if (min) return std::string(min_open ? "> " : ">= ") + format_number(*min);
  if (max) return std::string(max_open ? "< " : "<= ") + format_number(*max);
  return "any number";
}

std::string Range::condition(std::string_view name) const {
  if (min && max)
    return "satisfy " + format_number(*min) + (min_open ? " < " : " <= ") + std::string(name) +
           (max_open ? " < " : " <= ") + format_number(*max);
  return "be " + text();
}

std::vector<std::string> Table::names() const {
  std::vector<std::string> names;
  for (const auto& key : keys) names.push_back(key.name);
  return names;
}

const Key* Table::find(std::string_view name) const {
  for (const auto& key : keys)
    if (key.name == name) return &key;
  return nullptr;
}

const Key& Table::key(std::string_view name) const {
  if (const Key* found = find(name)) return *found;
  throw std::logic_error("schema: table '" + id + "' has no key '" + std::string(name) + "'");
}

namespace {

Range at_least(double min) { return Range{min, std::nullopt, false, false}; }
Range above(double min) { return Range{min, std::nullopt, true, false}; }
Range between(double min, double max, bool min_open, bool max_open) { return Range{min, max, min_open, max_open}; }

Key number(std::string name, std::string default_value, std::string meaning, std::optional<Range> range = {},
           std::string hint = {}) {
  return Key{std::move(name), Type::number, std::move(default_value), std::move(meaning), {}, range, std::move(hint)};
}
Key integer(std::string name, std::string default_value, std::string meaning, std::optional<Range> range = {},
            std::string hint = {}) {
  return Key{std::move(name), Type::integer, std::move(default_value), std::move(meaning), {}, range, std::move(hint)};
}
Key choice(std::string name, std::vector<std::string> choices, std::string default_value, std::string meaning) {
  return Key{std::move(name), Type::choice, std::move(default_value), std::move(meaning), std::move(choices), {}, {}};
}
Key of(Type type, std::string name, std::string default_value, std::string meaning) {
  return Key{std::move(name), type, std::move(default_value), std::move(meaning), {}, {}, {}};
}

std::vector<Key> joined(std::initializer_list<std::vector<Key>> parts) {
  std::vector<Key> keys;
  for (const auto& part : parts) keys.insert(keys.end(), part.begin(), part.end());
  return keys;
}

// The file-level keys every spelling starts with.
std::vector<Key> header_keys() {
  return {
      of(Type::string, "title", "the file name without extension", "used in the outputs"),
      choice("analysis", {"plane_strain", "plane_stress", "axisymmetric"}, "",
             "plane stress uses nu/(1+nu) in the plane-strain formulation (II.3.1)"),
      choice("interpolation", {"linear", "quadratic", "constant"}, "linear",
             "element order, the same for u and t; quadratic elements follow arcs exactly"),
      of(Type::table, "parameters", "none", "named constants and expressions of those above them"),
      of(Type::table, "mesh", "defaults", "mesh options ([mesh])"),
      of(Type::table, "output", "defaults", "output options ([output])"),
  };
}

// The keys of one body (one region) of any spelling.
std::vector<Key> body_keys() {
  return {
      of(Type::table, "material", "required", "the material ([material])"),
      of(Type::table, "vertices", "none", "named points: NAME = [x, y]"),
      of(Type::tables, "boundary", "required (or from geometry)", "boundary pieces, one table each"),
      of(Type::tables, "constraint", "none", "point constraints"),
      of(Type::string, "geometry", "none",
         "a Gmsh .geo or .msh file (relative to the problem file) whose physical curves are the boundary pieces "
         "(docs/gmsh.md)"),
      of(Type::table, "cells", "none (required with yield_stress)",
         "where the region may yield: its cells ([cells], docs/plasticity.md)"),
  };
}

std::vector<Key> piece_keys() {
  return {
      of(Type::name, "name", "`\"boundary<i>\"` (file order)",
         "unique, used in messages and outputs: at most 100 characters, no control characters"),
      choice("shape", {"line", "arc"}, "line", "a straight segment or a circular arc"),
      of(Type::point, "from", "required", "start point; the body lies to the left of the direction of travel"),
      of(Type::point, "to", "required", "end point"),
      of(Type::point, "center", "required for arcs", "arcs only: the centre"),
      choice("direction", {"ccw", "cw"}, "ccw", "arcs only: the sense of travel from `from` to `to` around `center`"),
      integer("elements", "1", "number of elements", at_least(1)),
      number("grading", "1 (uniform)", "ratio of the longest to the shortest element, sizes in geometric progression",
             at_least(1), "1 = uniform; to put the short elements at the other end use refine = \"end\""),
      choice("refine", {"start", "end"}, "start", "where the short elements of a graded piece go"),
      of(Type::boolean, "symmetry", "false",
         "a straight symmetry line of the body: it takes no elements and no conditions"),
  };
}

std::vector<Key> condition_keys() {
  return {
      of(Type::field, "u1", "free", "displacement along x (r)"),
      of(Type::field, "u2", "free", "displacement along y (z)"),
      of(Type::field, "t1", "0", "traction along x (r)"),
      of(Type::field, "t2", "0", "traction along y (z)"),
      of(Type::field, "un", "free", "displacement along the outward normal n"),
      of(Type::field, "ut", "free", "displacement along the tangent s = (-n_y, n_x), the direction of travel"),
      of(Type::field, "tn", "0", "normal traction (tn > 0 pulls outward)"),
      of(Type::field, "tt", "0", "tangential traction"),
      of(Type::field, "pressure", "0", "the same as tn = -pressure: a positive pressure pushes on the body"),
  };
}

std::vector<Key> interface_key() {
  return {of(Type::string, "interface", "none",
             "a bond: the region (subdomain) listing the same name is glued here; no condition")};
}

std::vector<Key> operator_keys() {
  return {
      choice("operator", {"auto", "dense", "compressed"}, "auto",
             "dense (LU, condition estimate), compressed (hierarchical matrices, H-LU) or auto (compressed from "
             "8 000 unknowns on, plane or axisymmetric; dense with two symmetry lines or without hmat-oss)"),
      number("accuracy", "1e-10 (smaller for fine elements on a large body)", "relative accuracy of the compressed blocks and of the H-LU (compressed only; by default 1e-6 h_min / L where that is smaller, down to 1e-11)",
             between(1e-14, 1e-2, false, false)),
  };
}

std::vector<Key> law_keys() {
  return {
      choice("kind", {"unilateral", "bilateral", "compliant"}, "unilateral",
             "bilateral: the pairs never separate (V.4); compliant: normal compliance, the pressure c_n pen^m_n of the "
             "interpenetration pen (docs/contact.md, Normal compliance)"),
      number("normal_stiffness", "required (compliant)", "compliant: c_n, the pressure at a unit interpenetration",
             above(0)),
      number("normal_exponent", "1", "compliant: m_n", at_least(1)),
      number("friction_stiffness", "normal_stiffness", "compliant, with friction: c_t of the threshold beta c_t pen^m_t",
             above(0)),
      number("friction_exponent", "normal_exponent", "compliant, with friction: m_t of the threshold beta c_t pen^m_t",
             at_least(1)),
      number("friction", "0 (frictionless)", "Coulomb's coefficient", at_least(0)),
      number("nonlocal_radius", "none (the local law)",
             "plane, with friction: the non-local Coulomb law's radius rho, the threshold beta (omega_rho * |p_n|) "
             "(docs/contact.md, Non-local friction)",
             above(0)),
      of(Type::boolean, "coupling", "true",
         "false: the uncoupled model (Spence's E.1), with friction only; the same in every contact"),
      number("wear_coefficient1", "0 (no wear)",
             "Archard's k of side 1: in each step its worn depth at a pair grows by k p_n |slip increment| "
             "(docs/contact.md, Wear)",
             at_least(0)),
      number("wear_coefficient2", "0 (no wear)", "the same for side 2 (an elastic body)", at_least(0)),
  };
}

std::vector<Key> pairing_keys() {
  return {
      choice("normal", {"common", "body1", "body2"}, "common", "the pair normal (V.2)"),
      choice("pairing", {"node_to_segment", "mortar"}, "node_to_segment",
             "the gap at side 1's nodes (node_to_segment), or weighted by side 1's dual shape functions over the "
             "overlaps of both meshes (mortar, elastic side 2: docs/contact.md, Mortar pairing)"),
      number("interference", "0", "initial overlap of the zones along the pair normal (shrink fit)", at_least(0)),
      of(Type::amplitude, "interference_amplitude", "the whole overlap from the first step",
         "the interference's history"),
      of(Type::field, "gap", "0",
         "a prescribed initial gap added to the geometric one, a function of side 1's node position; "
         "negative = overlap"),
  };
}

std::vector<Key> zone_keys() {
  return {
      number("contact_resolution", "none (the zone as declared and meshed)",
             "the boundaries are candidates: the solver finds where they touch and refines there until the pair "
             "spacing at the zone's edges is at most this fraction of its width (docs/contact.md, Candidate surfaces)",
             between(0, 1, true, true)),
      integer("max_adaptive_passes", "8", "contact_resolution: the most solves on refined meshes",
              between(1, 50, false, false)),
      integer("max_zone_elements", "5000", "contact_resolution: the most elements on each side's boundaries together",
              between(2, 200000, false, false)),
  };
}

std::vector<Key> contact_solver_keys() {
  return joined({
      {
          integer("increments", "16 with friction, 10 with an elastoplastic region, 1 otherwise",
                  "load steps over the history (the initial step count when adaptive)", between(1, 100000, false, false),
                  "over the limit of 100000 (each increment is a contact solve)"),
          choice("algorithm", {"newton", "thesis"}, "newton",
                 "semi-smooth Newton, or the thesis' algorithms (V.1-V.3)"),
          choice("contact_operator", {"auto", "dense", "matrix_free"}, "auto",
                 "the condensed operator formed (dense) or applied through the regions' factors (matrix_free: "
                 "any contact law, with or without friction; auto: from 2000 pairs on compressed regions, and a formed "
                 "operator of 400 pairs or more also compressed for the iterations' products; dense: its products "
                 "are the formed matrix's)"),
          number("tolerance", "1e-10",
                 "newton: relative residual of the complementarity functions (matrix-free: at least 1e-15 "
                 "pairs^1.5; a step whose contact set repeats at its solves' round-off is taken within 100 times "
                 "it, with a warning: docs/contact.md, Tolerance)",
                 between(0, 1, true, true)),
          integer("max_iterations", "100", "newton iterations per step; Kalker iterations (thesis)", at_least(1)),
          integer("gmres_restart", "3", "thesis only: m of GMRES(m) (Alg V.1)", at_least(1)),
          integer("max_gmres_cycles", "20000", "thesis only: cycles of Alg V.1 per threshold pass", at_least(1)),
          number("xi", "1e-8", "thesis only: the stopping tests of Alg V.1 (xi) and V.2 (sqrt(xi))",
                 between(0, 1, true, true)),
          of(Type::boolean, "record_steps", "false", "write the pairs and boundary fields of every step, into steps/"),
          of(Type::boolean, "adaptive", "true with friction",
             "redo a step shorter when too many pairs change state (friction only)"),
          integer("max_state_changes", "2", "adaptive: pairs of one contact that may change state in a step",
                  at_least(1)),
          integer("max_steps", "4096 (at least increments)", "adaptive: the most steps over the history"),
      },
      operator_keys(),
  });
}

std::vector<Key> named(std::string default_value, std::string meaning) {
  return {of(Type::name, "name", std::move(default_value), std::move(meaning))};
}

std::vector<Table> build_tables() {
  const std::string interior_meaning = "interior points ([interior])";
  std::vector<Table> t;
  // One-body files (docs/problem-file.md).
  t.push_back({"file", "top level", "the top level of the file",
               joined({header_keys(), body_keys(),
                       {of(Type::table, "interior", "none", interior_meaning),
                        of(Type::table, "solver", "defaults", "the operator ([solver])")}})});
  t.push_back({"material", "[material]", "the [material] table",
               {number("E", "required", "Young's modulus", above(0)),
                number("nu", "required", "Poisson's ratio", between(-1, 0.5, true, true)),
                number("yield_stress", "none (linear elastic)",
                       "Y: the von Mises yield stress in uniaxial tension; the region is elastoplastic "
                       "(docs/plasticity.md) and needs [cells]", above(0)),
                number("hardening", "0 (perfectly plastic)",
                       "H_iso: the yield stress grows by H_iso per unit equivalent plastic strain", at_least(0)),
                number("kinematic_hardening", "0",
                       "H_kin: the back stress grows by H_kin per unit plastic strain (Prager-Ziegler; uniaxial)",
                       at_least(0))}});
  t.push_back({"cells", "[cells]", "the [cells] table",
               {number("size", "required", "the cells' edge away from the refinement points", above(0)),
                of(Type::points, "box", "the whole region",
                   "[[x0, y0], [x1, y1]]: the cells fill the region's part in this rectangle (lower-left, upper-right)"),
                of(Type::points, "refine", "none", "[[x, y], ...]: points the cells are graded toward"),
                number("refine_size", "required with refine", "the cells' edge at the refinement points", above(0)),
                number("growth", "0.5", "with refine: the cells' edge grows by this per unit distance from the points",
                       above(0)),
                choice("shape", {"rectangles", "crossed"}, "rectangles",
                       "crossed: each rectangle cut by its diagonals into four triangles (docs/plasticity.md, Cells)"),
                choice("operator", {"dense", "compressed"}, "dense",
                       "the cells' operator: dense (the yielding cells' whole columns) or compressed (a hierarchical "
                       "matrix of the cells' direct fields, hmat-oss: less memory and faster increments at 8 000 cells, "
                       "but a costly set-up: slower in all up to about 15 000; docs/plasticity.md, Cost)"),
                of(Type::boolean, "nodes_at_cells", "true",
                   "the boundary's elements get end points where the cells' vertices lie on it, so that a collapse "
                   "mechanism leaves no stress (docs/plasticity.md, Cells); false keeps the mesh as given")}});
  t.push_back({"boundary", "[[boundary]]", "each [[boundary]] table", joined({piece_keys(), condition_keys()})});
  t.push_back({"tabulated", "a table of values", "a table of values",
               {of(Type::points, "table", "required",
                   "rows [coordinate, value], coordinates strictly increasing, at least two rows"),
                choice("along", {"x", "y", "r", "z"}, "",
                       "the coordinate the rows follow (r, z in axisymmetry); constant beyond the ends")}});
  t.push_back({"constraint", "[[constraint]]", "each [[constraint]] table",
               {of(Type::point, "at", "required", "a boundary point"),
                number("u1", "free", "displacement along x (r)"), number("u2", "free", "displacement along y (z)")}});
  t.push_back({"interior", "[interior]", "the [interior] table",
               {of(Type::points, "points", "none", "listed points [[x, y], ...]; one outside the body is an error"),
                of(Type::grid, "grid", "none",
                   "{ x = [min, max, count], y = [...] } (or r, z), or a list of them; points outside are dropped")}});
  t.push_back({"grid", "a grid table", "a grid table",
               {of(Type::points, "x", "required", "[min, max, count] along x (a count of 1 needs min = max)"),
                of(Type::points, "y", "required", "[min, max, count] along y"),
                of(Type::points, "r", "required", "axisymmetry: the same as x"),
                of(Type::points, "z", "required", "axisymmetry: the same as y")}});
  t.push_back({"mesh", "[mesh]", "the [mesh] table",
               {choice("continuity", {"continuous", "discontinuous"}, "continuous",
                       "discontinuous: every element has its own nodes, inside it (not with contact pairs)"),
                number("corner_shift", "0.2; discontinuous: the Gauss points, 0.2113 (linear), 0.1127 (quadratic)",
                       "where a split corner node sits, as a fraction of its element's length from the corner; "
                       "with discontinuous elements, where every element's end nodes sit",
                       between(0, 0.5, true, true)),
                number("corner_transition", "1.2",
                       "1 < g <= 4: growth factor of the grading toward a vertex where a much finer boundary meets "
                       "a coarser one; 0 keeps every boundary's elements as given")}});
  t.push_back({"solver", "[solver]", "the [solver] table", operator_keys()});
  t.push_back({"output", "[output]", "the [output] table",
               {of(Type::boolean, "vtk", "true", "also write the VTK files (boundary, interior)")}});
  // Decompositions (docs/domain-decomposition.md).
  t.push_back({"decomposition.file", "top level (with [[subdomain]])", "the top level of a file with subdomains",
               joined({header_keys(),
                       {of(Type::table, "decomposition", "defaults", "the interface solver ([decomposition])"),
                        of(Type::table, "vertices", "none", "vertices shared by every subdomain"),
                        of(Type::tables, "subdomain", "required", "one table per subdomain"),
                        of(Type::table, "solver", "defaults", "every subdomain's operator ([solver])")}})});
  t.push_back({"decomposition", "[decomposition]", "the [decomposition] table",
               {choice("method", {"conforming", "hybrid", "mixed"}, "conforming",
                       "the interface unknowns: displacements (IV.4), tractions (IV.5) or both (IV.6)"),
                choice("preconditioner", {"balancing", "none"}, "balancing with conforming, else none",
                       "balancing Neumann-Neumann (conforming only)"),
                integer("restart", "none while the basis fits in 256 MB", "m of GMRES(m)", at_least(1)),
                number("tolerance", "1e-8", "GMRES: ||r|| / ||r0|| (Alg IV.4)", between(0, 1, true, true)),
                integer("max_iterations", "500", "operator applications over all restarts", at_least(1)),
                number("interface_tolerance", "1e-6",
                       "facing interface nodes must coincide within this fraction of the geometry's size",
                       between(0, 0.1, true, true)),
                integer("displacement_nodes", "3", "mixed: nodes per interface carrying displacement continuity",
                        at_least(1)),
                of(Type::boolean, "explicit_operators", "false (true with balancing)",
                   "form each subdomain's interface map once instead of applying it matrix-free")}});
  t.push_back({"subdomain", "[[subdomain]]", "a [[subdomain]] table",
               joined({named("`\"subdomain<i>\"` (file order)", "the subdomain's name"), body_keys(),
                       {of(Type::table, "interior", "none", interior_meaning)}})});
  t.push_back({"region.boundary", "[[subdomain.boundary]]", "each boundary table",
               joined({piece_keys(), condition_keys(), interface_key()})});
  // Bodies and contacts (docs/contact.md).
  t.push_back({"contact.file", "top level (with [[body]])", "the top level of a contact file",
               joined({header_keys(),
                       {of(Type::tables, "body", "required", "the bodies"),
                        of(Type::table_or_tables, "contact", "none",
                           "[[contact]] tables, or the thesis' single [contact] table"),
                        of(Type::table, "solver", "defaults", "the contact solver and the operator ([solver])"),
                        of(Type::table_or_tables, "load", "none", "force loads ([load] or [[load]])"),
                        of(Type::table, "history", "none", "the load history ([history])")}})});
  t.push_back({"body", "[[body]]", "a [[body]] table",
               joined({named("`\"body[<i>]\"`", "the body's name (unique; output file names)"), body_keys(),
                       {of(Type::table, "interior", "none", interior_meaning)}})});
  t.push_back({"body.regions", "[[body]] of regions", "a [[body]] table with [[body.region]] tables (the body-level "
                                                      "keys go in each region)",
               joined({named("`\"body[<i>]\"`", "the body's name"),
                       {of(Type::tables, "region", "required", "the regions, bonded by interface names")}})});
  t.push_back({"body.rigid_body", "rigid [[body]]",
               "a rigid [[body]] table (a rigid body has a profile, no material or boundary)",
               joined({named("`\"body[<i>]\"`", "the body's name"),
                       {of(Type::table, "rigid", "required", "the profile and motion ([body.rigid])")}})});
  t.push_back({"region", "[[body.region]]", "a [[body.region]] table",
               joined({named("`\"<body>_<i>\"`", "the region's name"), body_keys(),
                       {of(Type::table, "interior", "none", interior_meaning)}})});
  t.push_back({"body.boundary", "[[body.boundary]]", "each boundary table",
               joined({piece_keys(), condition_keys(), interface_key(),
                       {of(Type::amplitude, "amplitude", "the body's data amplitude",
                           "the history of this boundary's prescribed values")}})});
  t.push_back({"rigid", "[body.rigid]", "a [body.rigid] table",
               {choice("profile", {"sphere", "cylinder", "flat", "cone", "contour", "rough"}, "",
                       "the rigid body's shape"),
                of(Type::point, "center", "required (sphere, cylinder, flat)",
                   "sphere, cylinder: the centre; flat: the middle of the face"),
                of(Type::point, "apex", "required (cone)", "cone: the apex"),
                number("radius", "required (sphere, cylinder)", "sphere, cylinder: the radius", above(0)),
                number("half_width", "required (flat)", "flat punch: the face |x - cx| <= a", above(0)),
                number("edge_radius", "0", "flat punch: the radius of its rounded edges", at_least(0)),
                number("half_angle", "required (cone)", "cone: degrees between the flank and the axis",
                       between(0, 90, true, true)),
                number("height", "twice the elastic bodies' size", "flat, cone: how far the sides rise", above(0)),
                of(Type::points, "points", "required (contour), or points_file",
                   "contour: a polyline [[x, y], ...], the body on its left"),
                of(Type::string, "points_file", "none",
                   "contour: instead of points, a CSV file of x, y per line (relative to the problem file; a header "
                   "line allowed; x increasing strictly; at most 100000 points): the body above it"),
                of(Type::point, "mean_line", "required (rough)",
                   "rough: the middle of the profile's mean line; the profile faces down (-y)"),
                number("length", "required (rough)", "rough: the profile's length along x, centred on mean_line",
                       above(0)),
                integer("samples", "required (rough)", "rough: the profile's points (spacing length / (samples - 1))",
                        between(2, 20000, false, false),
                        "the modes are summed at every sample: 20000 samples of 10000 modes take about a second"),
                number("hurst", "required (rough)", "rough: the Hurst exponent H; spectrum C(q) ~ q^-(1+2H)",
                       between(0, 1, true, true)),
                number("rms_height", "required (rough)", "rough: the RMS height of the samples about their mean",
                       above(0)),
                number("long_wavelength", "the length", "rough: the longest wavelength (<= length)", above(0)),
                number("short_wavelength", "required (rough)",
                       "rough: the shortest wavelength (>= 2 sample spacings)", above(0)),
                integer("seed", "0", "rough: the seed of the random phases (std::mt19937_64)",
                        between(0, 2147483647, false, false)),
                of(Type::point, "displacement", "none (a force in [load])",
                   "a prescribed translation at amplitude 1; a component along a force load must be 0 (the force moves the body along it)"),
                number("rotation", "none", "plane: a prescribed small rotation (radians, counter-clockwise)",
                       between(-0.1, 0.1, false, false), "the model is linear in it: a small rotation"),
                of(Type::amplitude, "amplitude", "a ramp over 0 <= t <= 1",
                   "the history of the prescribed displacement and rotation")}});
  t.push_back({"contact", "[[contact]]", "a [[contact]] table (solver keys go in [solver], a force in [load])",
               joined({named("`\"contact\"`, or `\"contact<k>\"`", "the contact's name (output files `<name>.csv`, ...)"),
                       {of(Type::string, "body1", "required", "side 1: an elastic body (the pairs are its nodes)"),
                        of(Type::strings, "boundary1", "required",
                           "side 1's boundary, or its boundaries joined end to start in the order of travel"),
                        of(Type::string, "body2", "required",
                           "side 2: an elastic body (body1 itself: self-contact) or a rigid body"),
                        of(Type::strings, "boundary2", "required (elastic side 2)",
                           "side 2's boundary, or its boundaries joined end to start in the order of travel")},
                       law_keys(), pairing_keys(), zone_keys()})});
  t.push_back({"contact.single", "[contact]", "the [contact] table",
               joined({{of(Type::strings, "boundary1", "required",
                           "the first [[body]]'s contact boundary, or its boundaries joined end to start in order"),
                        of(Type::strings, "boundary2", "required",
                           "the second [[body]]'s contact boundary, or its boundaries joined end to start in order"),
                        of(Type::table, "load", "none", "its force load ([contact.load])")},
                       law_keys(), pairing_keys(), zone_keys(), contact_solver_keys()})});
  t.push_back({"contact.solver", "[solver] (contact files)", "the [solver] table", contact_solver_keys()});
  t.push_back({"load", "[[load]]", "a load table",
               {of(Type::name, "name", "`\"<body>_<boundary>_<component>\"`", "for messages and motions.csv"),
                of(Type::string, "body", "required", "an elastic body (with boundary: a rigid platen) or a rigid body"),
                of(Type::string, "boundary", "none (rigid body)", "the loaded boundary of an elastic body"),
                integer("component", "required", "1: x (r), 2: y (z), 3: rotation of a rigid body (plane)",
                        between(1, 3, false, false)),
                number("force", "required",
                       "the integral of the traction component (2 pi r dr in axisymmetry), or the force (moment) on "
                       "a rigid body"),
                of(Type::amplitude, "amplitude", "a ramp over 0 <= t <= 1", "the force's history")}});
  t.push_back({"history", "[history]", "the [history] table",
               {number("end_time", "the last time of the amplitudes (1 without)",
                       "the end of the pseudo-time; one before an amplitude's last change leaves the rest out, with a "
                       "warning",
                       above(0)),
                of(Type::amplitude, "data_amplitude", "a ramp over 0 <= t <= 1",
                   "the history of every other prescribed value of the elastic bodies"),
                integer("cycles", "1",
                        "with wear: the load cycles the run stands for; the history from cycle_start to end_time "
                        "is one cycle, repeated (docs/contact.md, Wear)",
                        between(1, 1e9, false, false)),
                number("cycle_start", "required (cycles > 1)",
                       "cycles: where the repeated cycle starts; the loads at cycle_start and end_time must agree",
                       at_least(0)),
                integer("cycle_jump", "none (adaptive)",
                        "cycles: each computed cycle stands for this many (fixed), instead of the adaptive jump",
                        between(1, 1e9, false, false)),
                integer("max_cycle_jump", "cycles / 20 (at least 1)", "cycles, adaptive: the largest jump",
                        between(1, 1e9, false, false)),
                number("max_pressure_change", "0.05",
                       "cycles, adaptive: the largest pressure change a jump may cause, as a fraction of the peak "
                       "pressure (a larger one is undone and the jump halved)",
                       between(0, 1, true, true))}});
  t.push_back({"amplitude.cyclic", "a cyclic amplitude", "a cyclic amplitude",
               {number("mean", "0", "the value the triangle wave starts from and returns to"),
                number("amplitude", "required", "the wave goes up to mean + amplitude and down to mean - amplitude"),
                integer("cycles", "1", "the number of cycles", between(1, 10000, false, false)),
                number("start", "0", "the time the first cycle starts", at_least(0)),
                number("period", "1", "one whole cycle", above(0))}});
  return t;
}

}  // namespace

const std::vector<Table>& tables() {
  static const std::vector<Table> all = build_tables();
  return all;
}

const Table& table(std::string_view id) {
  for (const auto& t : tables())
    if (t.id == id) return t;
  throw std::logic_error("schema: no table '" + std::string(id) + "'");
}

std::string type_text(const Key& key) {
  auto quoted_choices = [&] {
    std::string text;
    for (std::size_t i = 0; i < key.choices.size(); ++i) {
      if (i) text += i + 1 == key.choices.size() ? " or " : ", ";
      text += "`\"" + key.choices[i] + "\"`";
    }
    return text;
  };
  auto with_range = [&](std::string text) { return key.range ? text + " " + key.range->text() : text; };
  switch (key.type) {
    case Type::number: return with_range("number");
    case Type::integer: return with_range("integer");
    case Type::boolean: return "`true` or `false`";
    case Type::string: return "string";
    case Type::strings: return "string or list of strings";
    case Type::name: return "name";
    case Type::choice: return quoted_choices();
    case Type::point: return "vertex name or `[x, y]`";
    case Type::points: return "list";
    case Type::field: return "number, expression of x, y or `{ table, along }`";
    case Type::amplitude: return "`[[t, value], ...]` or `{ mean, amplitude, cycles, start, period }`";
    case Type::table: return "table";
    case Type::tables: return "tables";
    case Type::table_or_tables: return "table or tables";
    case Type::grid: return "table or list of tables";
  }
  return {};
}

std::string markdown(const Table& table) {
  std::string text = "| key | value | default | meaning |\n|---|---|---|---|";
  for (const auto& key : table.keys) {
    std::string default_text = key.default_value;
    const auto& choices = key.choices;
    if (key.type == Type::choice && default_text.empty()) default_text = "required";
    if (std::find(choices.begin(), choices.end(), default_text) != choices.end())
      default_text = "`\"" + default_text + "\"`";
    text += "\n| `" + key.name + "` | " + type_text(key) + " | " + default_text + " | " + key.meaning + " |";
  }
  return text;
}

std::string reference_markdown() {
  std::string text =
      "# Every key of a problem file\n\n"
      "Generated from the schema the readers check (src/io/input/problem_schema.cpp) by\n"
      "`bemcontact keys --write-docs docs`; test `SchemaDocs.*` keeps it and the key tables of the\n"
      "other pages equal to it. Numbers and integers may be expressions of the parameters in\n"
      "quotes (docs/problem-file.md, Numbers); a range is checked on the value. Each table is\n"
      "named by its id (`bemcontact keys ID` prints one).\n";
  for (const auto& t : tables())
    text += "\n## " + t.title + " (`" + t.id + "`)\n\nIn messages: " + t.section + ".\n\n" + markdown(t) + "\n";
  return text;
}

std::string with_key_tables(const std::string& text) {
  static const std::string open = "<!-- keys: ", close = "<!-- end keys -->";
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t start = text.find(open, at);
    if (start == std::string::npos) break;
    const std::size_t id_end = text.find(" -->", start);
    const std::size_t end = text.find(close, start);
    if (id_end == std::string::npos || end == std::string::npos)
      throw std::invalid_argument("a '" + open + "' block without its '" + close + "'");
    const std::string id = text.substr(start + open.size(), id_end - start - open.size());
    try {
      (void)table(id);
    } catch (const std::logic_error&) {
      throw std::invalid_argument("no key table '" + id + "' (bemcontact keys --list)");
    }
    out += text.substr(at, id_end + 4 - at) + "\n" + markdown(table(id)) + "\n";
    at = end;
  }
  return out + text.substr(at);
}

std::string section_of(std::string_view key, std::string_view section) {
  // Tables a user could plausibly confuse; the root table comes first. For a contact, only
  // its law: its other keys are not misplaced elsewhere.
  const std::pair<const char*, std::vector<std::string>> sections[] = {
      {"the top level of the file", table("file").names()},
      {"the [material] table", table("material").names()},
      {"each [[boundary]] table", table("boundary").names()},
      {"each [[constraint]] table", table("constraint").names()},
      {"the [interior] table", table("interior").names()},
      {"the [mesh] table", table("mesh").names()},
      {"the [output] table", table("output").names()},
      {"the [solver] table", table("solver").names()},
      {"each [[contact]] table (the law of that contact; or the single [contact] table)", {"kind", "friction",
                                                                                           "coupling"}},
  };
  // A body's own tables: top-level tables in a one-body file, but written under the body
  // (or region) in a file of bodies, so "the top level" would send the user astray.
  for (const char* body_table : {"material", "cells", "interior", "vertices"})
    if (key == body_table)
      return "a table of its own, of the body or region: [" + std::string(key) + "] in a one-body file, [body." +
             std::string(key) + "] or [body.region." + std::string(key) + "] in a file of bodies";
  for (const auto& [name, keys] : sections) {
    if (section == name) continue;
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) return name;
  }
  return {};
}

}  // namespace bemcontact::io::schema
