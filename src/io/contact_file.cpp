#include "bemcontact/io/contact_file.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/io/body_parser.hpp"
#include "bemcontact/io/expression.hpp"
#include "bemcontact/io/toml_reader.hpp"

namespace bemcontact::io {
namespace {



std::vector<Vec2> read_points(const TableReader& body, const FileContext& context) {
  std::vector<Vec2> points;
  const toml::table* table = body.optional_table("interior", "[body.interior]");
  if (!table) return points;
  const TableReader interior(*table, body.key_path("interior"), context, body.line());
  interior.check_keys({"points", "grid"}, "the [body.interior] table");
  if (const toml::node* node = interior.find("points")) {
    const toml::array* list = node->as_array();
    if (!list) interior.fail("points", "must be a list of points " + context.point_form() + ", found " + describe_node(*node));
    for (const toml::node& point : *list) points.push_back(read_point(point, interior.where("points"), context));
  }
  if (const toml::table* grid = interior.optional_table("grid", "grid"))
    for (const auto& point : read_interior_grid(TableReader(*grid, interior.key_path("grid"), context, interior.line()),
                                                context))
      points.push_back(point.position);
  return points;
}

int piece_named(const bem::BodyDefinition& body, const std::string& name, const TableReader& reader,
                std::string_view key) {
  std::string names;
  for (std::size_t k = 0; k < body.pieces.size(); ++k) {
    if (body.pieces[k].name == name) return static_cast<int>(k);
    names += (k ? ", '" : "'") + body.pieces[k].name + "'";
  }
  reader.fail(key, "body '" + body.name + "' has no boundary named '" + name + "'; its boundaries are " + names);
}

}  // namespace

bool is_contact_text(std::string_view text) {
  try {
    const toml::table root = toml::parse(text);
    return root.contains("contact");
  } catch (...) {
    return false;
  }
}

bool is_contact_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return false;
  std::ostringstream text;
  text << in.rdbuf();
  return is_contact_text(text.str());
}

ContactFile read_contact_file(const std::filesystem::path& path, const ParameterOverrides& overrides) {
  return parse_contact_problem(read_problem_text(path), path.string(), overrides);
}

ContactFile parse_contact_problem(std::string_view text, const std::string& file_name,
                                  const ParameterOverrides& overrides,
    const ResourceLimits& limits) {
  const toml::table root_table = parse_toml_text(text, file_name);
  ContactFile result;
  FileContext context;
  context.overrides = overrides;
  context.limits = limits;
  context.file = file_name;
  const TableReader root(root_table, "", context, 1);
  root.check_keys({"title", "analysis", "interpolation", "parameters", "mesh", "output", "body", "contact"},
                  "the top level of a contact file");
  auto& problem = result.problem;
  problem.source_file = file_name;
  read_file_header(root, context, file_name, problem.analysis, problem.title, problem.mesh.interpolation);
  if (problem.mesh.interpolation == Interpolation::constant)
    root.fail("interpolation", "contact problems need linear or quadratic elements (the pairs are formed at "
                               "body 1's nodes, projected on body 2's elements)");
  result.parameters = context.parameters;
  read_mesh_options(root, context, problem.mesh);
  if (const toml::table* output = root.optional_table("output", "[output]")) {
    const TableReader reader(*output, "output", context, root.line());
    reader.check_keys({"vtk"}, "the [output] table");
    result.vtk = reader.boolean_or("vtk", true);
  }

  // The two bodies.
  const toml::node* bodies_node = root.find("body");
  const toml::array* bodies = bodies_node ? bodies_node->as_array() : nullptr;
  if (!bodies || !bodies->is_array_of_tables() || bodies->size() != 2)
    root.fail("body", "a contact file needs exactly two [[body]] tables (found " +
                          (bodies_node ? describe_node(*bodies_node) : std::string("none")) + ")");
  for (int b = 0; b < 2; ++b) {
    const toml::table& table = *bodies->get(static_cast<std::size_t>(b))->as_table();
    const std::string path = "body[" + std::to_string(b + 1) + "]";
    const int line = line_of(*bodies->get(static_cast<std::size_t>(b))) > 0 ? line_of(*bodies->get(static_cast<std::size_t>(b))) : 1;
    problem.bodies[b] = parse_body(table, BodyContext{&context, path, {"name", "interior"}, line});
    const TableReader reader(table, path, context, line);
    problem.bodies[b].name = reader.optional_string("name").value_or(path);
    problem.interior_points[b] = read_points(reader, context);
  }
  // Body 2's nodes on the zone are placed on body 1's common normals, so mesh keys there
  // would have no effect.
  if (problem.bodies[0].name == problem.bodies[1].name)
    root.fail("body", "the two bodies have the same name '" + problem.bodies[0].name + "'");

  // [contact]
  const toml::table* contact_table = root.optional_table("contact", "[contact]");
  if (!contact_table) root.fail("contact", "missing [contact] table");
  const TableReader contact(*contact_table, "contact", context, root.line());
  contact.check_keys({"boundary1", "boundary2", "kind", "friction", "coupling", "increments", "algorithm",
                      "gmres_restart", "max_gmres_cycles", "xi", "tolerance", "max_iterations", "record_steps", "load",
                      "normal", "interference"},
                     "the [contact] table");
  for (int b = 0; b < 2; ++b) {
    const std::string key = "boundary" + std::to_string(b + 1);
    const auto name = contact.optional_string(key);
    if (!name) contact.fail(key, "missing: name the boundary of body '" + problem.bodies[b].name + "' in contact");
    problem.contact_piece[b] = piece_named(problem.bodies[b], *name, contact, key);
    const auto& condition = problem.bodies[b].conditions[problem.contact_piece[b]];
    if (condition.kind[0] == bem::ConditionKind::displacement || condition.kind[1] == bem::ConditionKind::displacement ||
        condition.value[0] || condition.value[1])
      contact.fail(key, "boundary '" + *name + "' of body '" + problem.bodies[b].name +
                            "' carries conditions; a contact boundary must have none (the contact sets them)");
  }
  problem.kind = contact.choice("kind", {"unilateral", "bilateral"}, "unilateral") == "bilateral"
                     ? contact::ContactKind::bilateral
                     : contact::ContactKind::unilateral;
  problem.friction = contact.optional_number("friction").value_or(0.0);
  if (!(problem.friction >= 0.0)) contact.fail("friction", "the friction coefficient must be >= 0");
  problem.tangential_coupling = contact.boolean_or("coupling", true);
  if (contact.has("coupling") && problem.friction == 0.0)
    contact.fail("coupling", "'coupling' acts on the tangential tractions of friction; with friction = 0 it has "
                             "no effect (remove it, or give a friction coefficient)");
  problem.interference = contact.optional_number("interference").value_or(0.0);
  if (!(problem.interference >= 0.0 && std::isfinite(problem.interference)))
    contact.fail("interference", "the interference (initial overlap of the contact zones along the pair normal, "
                                 "e.g. the radial interference of a shrink fit) must be a finite number >= 0, found " +
                                     format_number(problem.interference));
  const std::string normal = contact.choice("normal", {"common", "body1", "body2"}, "common");
  problem.pair_normal = normal == "body1"   ? contact::PairNormal::body1
                        : normal == "body2" ? contact::PairNormal::body2
                                            : contact::PairNormal::common;
  problem.increments = contact.integer_or("increments", problem.friction > 0.0 ? 16 : 1);
  if (problem.increments < 1) contact.fail("increments", "the number of load increments must be >= 1");
  if (problem.increments > 100000)
    contact.fail("increments", std::to_string(problem.increments) +
                                   " load increments is over the limit of 100000 (each one is a contact solve)");
  problem.record_steps = contact.boolean_or("record_steps", false);
  problem.solver.algorithm = contact.choice("algorithm", {"newton", "thesis"}, "newton") == "thesis"
                                 ? contact::Algorithm::thesis
                                 : contact::Algorithm::newton;
  problem.solver.gmres_restart = contact.integer_or("gmres_restart", problem.solver.gmres_restart);
  if (problem.solver.gmres_restart < 1) contact.fail("gmres_restart", "m of GMRES(m) must be >= 1");
  problem.solver.max_gmres_cycles = contact.integer_or("max_gmres_cycles", problem.solver.max_gmres_cycles);
  if (problem.solver.max_gmres_cycles < 1) contact.fail("max_gmres_cycles", "must be >= 1");
  if (const auto xi = contact.optional_number("xi")) {
    if (!(*xi > 0.0 && *xi < 1.0)) contact.fail("xi", "must satisfy 0 < xi < 1");
    problem.solver.xi = *xi;
  }
  if (const auto tolerance = contact.optional_number("tolerance")) {
    if (!(*tolerance > 0.0 && *tolerance < 1.0)) contact.fail("tolerance", "must satisfy 0 < tolerance < 1");
    problem.solver.tolerance = *tolerance;
  }
  if (problem.solver.algorithm != contact::Algorithm::thesis)
    for (const char* thesis_key : {"gmres_restart", "max_gmres_cycles", "xi"})
      if (contact.has(thesis_key))
        contact.fail(thesis_key, "'" + std::string(thesis_key) +
                                     "' tunes the thesis algorithm only; it has no effect with algorithm = \"newton\" "
                                     "(remove it, or set algorithm = \"thesis\")");
  if (problem.solver.algorithm == contact::Algorithm::thesis && contact.has("tolerance"))
    contact.fail("tolerance", "'tolerance' is the Newton algorithm's; the thesis algorithm stops on xi (give xi "
                              "instead, or set algorithm = \"newton\")");
  problem.solver.max_iterations = contact.integer_or("max_iterations", problem.solver.max_iterations);
  if (problem.solver.max_iterations < 1) contact.fail("max_iterations", "must be >= 1");

  if (const toml::table* load_table = contact.optional_table("load", "[contact.load]")) {
    const TableReader load(*load_table, "contact.load", context, contact.line());
    load.check_keys({"body", "boundary", "component", "force"}, "the [contact.load] table");
    contact::ForceLoad force;
    const auto body_name = load.optional_string("body");
    if (!body_name) load.fail("body", "missing: the body that carries the force");
    force.body = -1;
    for (int b = 0; b < 2; ++b)
      if (problem.bodies[b].name == *body_name) force.body = b;
    if (force.body < 0)
      load.fail("body", "no body named '" + *body_name + "'; the bodies are '" + problem.bodies[0].name + "' and '" +
                            problem.bodies[1].name + "'");
    const auto boundary = load.optional_string("boundary");
    if (!boundary) load.fail("boundary", "missing: the boundary that carries the force");
    force.piece = piece_named(problem.bodies[force.body], *boundary, load, "boundary");
    if (force.piece == problem.contact_piece[force.body])
      load.fail("boundary", "the force cannot act on the contact boundary itself");
    if (problem.bodies[force.body].conditions[force.piece].signature != "free")
      load.fail("boundary", "boundary '" + *boundary + "' of body '" + *body_name +
                                "' carries conditions, but a boundary under [contact.load] moves as a rigid platen "
                                "(its displacement along the force is the unknown approach, the other component is "
                                "held at 0), so they would have no effect; remove them");
    const int component = load.integer_or("component", 2);
    if (component != 1 && component != 2) load.fail("component", "must be 1 or 2");
    force.component = component - 1;
    force.force = load.number("force");
    if (force.force == 0.0) load.fail("force", "the total force must not be zero");
    problem.force = force;
  }

  // Pair the zone now, so that geometric errors point at the [contact] table.
  try {
    (void)contact::prepare_contact(problem);
  } catch (const GeometryError& error) {
    throw InputError(contact.where("boundary1"), error.what());
  }
  result.warnings = context.warnings;
  return result;
}

}  // namespace bemcontact::io
