#include "bemcontact/io/input/contact_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include <toml++/toml.h>

#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/contact/rigid_profile.hpp"
#include "bemcontact/contact/rough_profile.hpp"
#include "io/input/body_parser.hpp"
#include "bemcontact/io/input/decomposition_file.hpp"
#include "io/input/region_parser.hpp"
#include "bemcontact/io/input/problem_schema.hpp"
#include "bemcontact/io/input/expression.hpp"
#include "io/input/readers.hpp"
#include "io/input/toml_reader.hpp"
#include "bemcontact/io/text_format.hpp"
#include "bemcontact/io/file_names.hpp"
#include "bemcontact/io/input/problem_text.hpp"
#include "bemcontact/io/input/profile_file.hpp"

namespace bemcontact::io {
namespace {

constexpr double kPi = 3.141592653589793;

// A boundary of an elastic body by name, searched in all its regions.
contact::BoundaryRef boundary_named(const contact::ContactProblem& problem, int body, const std::string& name,
                                    const TableReader& reader, std::string_view key) {
  const auto& b = problem.bodies[body];
  contact::BoundaryRef found;
  std::string names;
  for (std::size_t r = 0; r < b.regions.size(); ++r)
    for (std::size_t k = 0; k < b.regions[r].body.pieces.size(); ++k) {
      const auto& piece = b.regions[r].body.pieces[k];
      if (piece.name == name) {
        if (!found.whole_contour())
          reader.fail(key, "body '" + b.name + "' has two boundaries named '" + name + "' (regions '" +
                               b.regions[found.region].body.name + "' and '" + b.regions[r].body.name +
                               "'); rename one");
        found = {body, static_cast<int>(r), {static_cast<int>(k)}};
      }
      names += (names.empty() ? "'" : ", '") + piece.name + "'";
    }
  if (found.whole_contour()) reader.fail(key, "body '" + b.name + "' has no boundary named '" + name + "'; its boundaries are " + names);
  return found;
}

int body_named(const contact::ContactProblem& problem, const std::string& name, const TableReader& reader,
               std::string_view key) {
  std::string names;
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    if (problem.bodies[b].name == name) return static_cast<int>(b);
    names += (b ? ", '" : "'") + problem.bodies[b].name + "'";
  }
  reader.fail(key, "no body named '" + name + "'; the bodies are " + names);
}

// The size of the elastic bodies (for the extent of rigid profiles' sides).
double elastic_extent(const contact::ContactProblem& problem) {
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions)
      for (const auto& piece : region.body.pieces)
        for (const Vec2& p : {piece.start, piece.end}) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return std::isfinite(lo.x()) ? (hi - lo).maxCoeff() : 1.0;
}

// An amplitude: a table [[t, value], ...] with t increasing, or the cyclic shorthand
// { mean, amplitude, cycles, start = 0, period = 1 }: a triangle wave from the mean up to
// mean + amplitude, down to mean - amplitude and back, `cycles` times from `start`.
contact::Amplitude read_amplitude(const TableReader& reader, std::string_view key) {
  contact::Amplitude amplitude;
  const toml::node& node = *reader.find(key);
  const FileContext& context = reader.context();
  if (const toml::table* table = node.as_table()) {
    const TableReader cyclic(*table, reader.key_path(key), context, reader.line());
    cyclic.check_keys(schema::table("amplitude.cyclic"));
    const double mean = cyclic.optional_number("mean").value_or(0.0);
    const double size = cyclic.number("amplitude");
    const int cycles = cyclic.integer_or("cycles", 1);
    const double start = cyclic.optional_number("start").value_or(0.0);
    const double period = cyclic.optional_number("period").value_or(1.0);
    amplitude.points.emplace_back(start, mean);
    for (int c = 0; c < cycles; ++c) {
      const double t0 = start + c * period;
      amplitude.points.emplace_back(t0 + 0.25 * period, mean + size);
      amplitude.points.emplace_back(t0 + 0.75 * period, mean - size);
      amplitude.points.emplace_back(t0 + period, mean);
    }
    return amplitude;
  }
  const toml::array* list = node.as_array();
  if (!list || list->empty())
    reader.fail(key, "must be a table of points [[t, value], ...] or a cyclic amplitude { mean, amplitude, cycles, "
                     "start, period }");
  for (const toml::node& point : *list) {
    const Vec2 p = read_point(point, reader.where(key), context);
    if (!amplitude.points.empty() && !(p.x() > amplitude.points.back().x()))
      reader.fail(key, "the times of the amplitude must increase, found " + format_number(p.x()) + " after " +
                           format_number(amplitude.points.back().x()));
    if (p.x() < 0.0) reader.fail(key, "the times of the amplitude must be >= 0");
    amplitude.points.push_back(p);
  }
  return amplitude;
}

// A contour's points: the list `points`, or the CSV file `points_file` (relative to the
// problem file's folder; its errors name the CSV file and line).
std::vector<Vec2> read_contour_points(const TableReader& rigid, const FileContext& context) {
  if (rigid.has("points") && rigid.has("points_file"))
    rigid.fail("points_file", "give the contour's points either as a list (points) or as a file (points_file), not both");
  if (rigid.has("points_file")) {
    const auto name = rigid.optional_string("points_file");
    if (!name || name->empty()) rigid.fail("points_file", "the profile's CSV file (x, y per line) as a string");
    std::filesystem::path file(*name);
    if (file.is_relative() && !context.file.empty() && context.file.front() != '<')
      file = std::filesystem::path(context.file).parent_path() / file;
    return read_profile_points(file, rigid.key_path("points_file"));
  }
  const toml::node& node = rigid.require("points", "a list of points, or points_file = \"profile.csv\"");
  const toml::array* list = node.as_array();
  if (!list) rigid.fail("points", "must be a list of points [" + context.point_form() + ", ...]");
  std::vector<Vec2> points;
  for (const toml::node& point : *list) points.push_back(read_point(point, rigid.where("points"), context));
  return points;
}

// A rough profile's spectrum and samples; the relations between the keys named by the key
// that breaks them.
contact::RoughProfileSpec read_rough_spec(const TableReader& rigid, const FileContext& context) {
  contact::RoughProfileSpec spec;
  spec.length = rigid.number("length");
  spec.samples = read_integer(rigid.require("samples", "an integer"), rigid.where("samples"), context);
  spec.hurst = rigid.number("hurst");
  spec.rms_height = rigid.number("rms_height");
  spec.long_wavelength = rigid.optional_number("long_wavelength").value_or(spec.length);
  spec.short_wavelength = rigid.number("short_wavelength");
  spec.seed = static_cast<std::uint64_t>(rigid.integer_or("seed", 0));
  if (spec.long_wavelength > spec.length)
    rigid.fail("long_wavelength", "the long cut-off " + format_number(spec.long_wavelength) +
                                      " exceeds the profile's length " + format_number(spec.length) +
                                      ": the profile holds no longer mode");
  if (spec.short_wavelength > spec.long_wavelength)
    rigid.fail("short_wavelength", "the short cut-off " + format_number(spec.short_wavelength) +
                                       " exceeds the long one " + format_number(spec.long_wavelength));
  if (const std::string problem = contact::rough_profile_problem(spec); !problem.empty())
    rigid.fail(problem.find("Nyquist") != std::string::npos || problem.find("no mode") != std::string::npos
                   ? "short_wavelength"
                   : "profile",
               "rough profile: " + problem);
  return spec;
}

contact::RigidBody read_rigid(const TableReader& rigid, const FileContext& context, double extent) {
  rigid.check_keys(schema::table("rigid"));
  contact::ProfileShape shape;
  shape.profile = rigid.choice("profile");
  if (shape.profile.empty()) rigid.fail("profile", "missing: sphere, cylinder, flat, cone, contour or rough");
  const bool round = shape.profile == "sphere" || shape.profile == "cylinder";
  auto only_for = [&](const char* key, bool allowed, const std::string& which) {
    if (rigid.has(key) && !allowed)
      rigid.fail(key, "'" + std::string(key) + "' applies to the " + which + " profile only; it has no effect on a " +
                          shape.profile);
  };
  only_for("radius", round, "sphere and cylinder");
  only_for("half_width", shape.profile == "flat", "flat");
  only_for("edge_radius", shape.profile == "flat", "flat");
  only_for("half_angle", shape.profile == "cone", "cone");
  only_for("apex", shape.profile == "cone", "cone");
  only_for("center", shape.profile != "cone" && shape.profile != "contour" && shape.profile != "rough",
           "sphere, cylinder and flat");
  only_for("height", shape.profile == "flat" || shape.profile == "cone", "flat and cone");
  only_for("points", shape.profile == "contour", "contour");
  only_for("points_file", shape.profile == "contour", "contour");
  for (const char* key : {"mean_line", "length", "samples", "hurst", "rms_height", "long_wavelength",
                          "short_wavelength", "seed"})
    only_for(key, shape.profile == "rough", "rough");
  const char* position_key = shape.profile == "cone" ? "apex" : shape.profile == "rough" ? "mean_line" : "center";
  if (shape.profile != "contour")
    shape.center = read_point(rigid.require(position_key, "a point " + context.point_form()), rigid.where(position_key),
                              context);
  if (round) shape.radius = rigid.number("radius");
  if (shape.profile == "flat") {
    shape.half_width = rigid.number("half_width");
    shape.edge_radius = rigid.optional_number("edge_radius").value_or(0.0);
  }
  if (shape.profile == "cone") {
    const double degrees = rigid.number("half_angle");
    if (!(degrees > 0.0 && degrees < 90.0)) rigid.fail("half_angle", "the cone's half-angle must be in (0, 90) degrees");
    shape.half_angle = degrees * kPi / 180.0;
  }
  shape.height = rigid.optional_number("height").value_or(2.0 * extent + 2.0 * shape.half_width + shape.edge_radius);
  if (shape.profile == "contour") shape.points = read_contour_points(rigid, context);
  if (shape.profile == "rough") shape.rough = read_rough_spec(rigid, context);
  contact::RigidBody body;
  body.profile = shape.profile;
  if (shape.profile != "contour") body.reference = shape.center;
  try {
    body.contour = contact::rigid_contour(shape);
  } catch (const GeometryError& error) {
    rigid.fail("profile", error.what());
  }
  if (const toml::node* node = rigid.find("displacement"))
    body.displacement = read_point(*node, rigid.where("displacement"), context);
  if (rigid.has("rotation")) {
    if (!body.reference)
      rigid.fail("rotation", "a contour has no centre to rotate about (use a profile with a center)");
    body.rotation = rigid.number("rotation");
  }
  if (rigid.has("amplitude")) {
    if (!body.displacement && !body.rotation)
      rigid.fail("amplitude", "the amplitude is that of the displacement or rotation, neither of which is given");
    body.amplitude = read_amplitude(rigid, "amplitude");
  }
  return body;
}

// Boundaries with their own amplitude (amplitude = ... in a boundary table): read and
// removed from the table before the body is parsed; their conditions get a load group.
struct BoundaryAmplitudes {
  std::vector<int> group;                 // per boundary table: load group (0: the data amplitude)
  std::vector<SourceLocation> where;
};
BoundaryAmplitudes take_boundary_amplitudes(toml::table& table, const std::string& path, FileContext& context, int line,
                                            contact::ContactProblem& problem) {
  BoundaryAmplitudes out;
  toml::array* boundaries = table.get("boundary") ? table.get("boundary")->as_array() : nullptr;
  if (!boundaries || !boundaries->is_array_of_tables()) return out;
  int b = 0;
  for (toml::node& node : *boundaries) {
    ++b;
    toml::table& boundary = *node.as_table();
    const TableReader reader(boundary, path + ".boundary[" + std::to_string(b) + "]", context, line);
    int group = 0;
    SourceLocation where;
    if (reader.has("amplitude")) {
      problem.boundary_amplitudes.push_back(read_amplitude(reader, "amplitude"));
      group = static_cast<int>(problem.boundary_amplitudes.size());
      where = reader.where("amplitude");
      boundary.erase("amplitude");
    }
    out.group.push_back(group);
    out.where.push_back(where);
  }
  return out;
}

void set_load_groups(dd::Subdomain& region, const BoundaryAmplitudes& amplitudes) {
  for (std::size_t k = 0; k < amplitudes.group.size() && k < region.body.conditions.size(); ++k) {
    if (amplitudes.group[k] == 0) continue;
    auto& condition = region.body.conditions[k];
    if (!condition.value[0] && !condition.value[1])
      throw InputError(amplitudes.where[k], "boundary '" + region.body.pieces[k].name +
                                                "' prescribes no nonzero value: its amplitude would have no effect");
    condition.load_group = amplitudes.group[k];
  }
}

// The output files named after regions and contacts, by whose name and line they are:
// two names must not give one file (names that differ only in characters written as '_',
// a contact named like a body's file, "motions").
class OutputNames {
 public:
  OutputNames() {
    for (const auto& file : model_file_names()) owners_.emplace(file, Owner{"the run's own " + file, 0});
  }
  void claim(const TableReader& reader, const std::vector<std::string>& files, const std::string& owner) {
    for (const auto& file : files) {
      const auto [existing, added] = owners_.emplace(file, Owner{owner, reader.where("name").line});
      if (added) continue;
      const std::string other =
          existing->second.line > 0 ? existing->second.what + " (line " + std::to_string(existing->second.line) + ")"
                                    : existing->second.what;
      reader.fail("name", "the output file '" + file + "' of " + owner + " would also be that of " + other +
                              " (file names keep letters and digits and write every other character as '_'): "
                              "choose another name");
    }
  }

 private:
  struct Owner {
    std::string what;
    int line;
  };
  std::map<std::string, Owner> owners_;
};

void read_bodies(toml::table& root_table, const TableReader& root, FileContext& context,
                 contact::ContactProblem& problem, OutputNames& output_names) {
  toml::node* bodies_node = root_table.get("body");
  toml::array* bodies = bodies_node ? bodies_node->as_array() : nullptr;
  if (!bodies || !bodies->is_array_of_tables() || bodies->empty())
    root.fail("body", "must be one or more [[body]] tables (found " +
                          (bodies_node ? describe_node(*bodies_node) : std::string("none")) + ")");
  std::map<std::string, int> body_lines, region_lines;
  std::vector<const TableReader*> rigid_readers;
  int index = 0;
  for (toml::node& node : *bodies) {
    ++index;
    toml::table& table = *node.as_table();
    const std::string path = "body[" + std::to_string(index) + "]";
    const int line = line_of(node) > 0 ? line_of(node) : root.line();
    const TableReader reader(table, path, context, line);
    contact::Body body;
    body.where = SourceLocation{context.file, reader.line(), path};
    body.name = reader.optional_name("name").value_or(path);
    if (body.name.empty()) reader.fail("name", "the name must not be empty");
    body.named = true;
    if (const auto [existing, inserted] = body_lines.emplace(body.name, reader.line()); !inserted)
      reader.fail("name", "the body name '" + body.name + "' is already used at line " +
                              std::to_string(existing->second) + "; body names must be unique");
    auto add_region_name = [&](const std::string& name, const TableReader& where, const char* kind) {
      if (const auto [existing, inserted] = region_lines.emplace(name, where.line()); !inserted && existing->second != where.line())
        where.fail("name", "the name '" + name + "' is already used at line " + std::to_string(existing->second) +
                               " (the output files are named after bodies and regions)");
      else if (inserted)
        output_names.claim(where, region_file_names(name), kind + (" '" + name + "'"));
    };
    if (reader.has("rigid")) {
      reader.check_keys(schema::table("body.rigid_body"));
      body.regions.clear();
      problem.bodies.push_back(std::move(body));  // the profile is read once every elastic body is known
      continue;
    }
    if (reader.has("region")) {
      reader.check_keys(schema::table("body.regions"));
      toml::array* regions = table.get("region")->as_array();
      if (!regions || !regions->is_array_of_tables() || regions->empty())
        reader.fail("region", "must be one or more [[body.region]] tables");
      int r = 0;
      for (toml::node& region_node : *regions) {
        ++r;
        toml::table& region_table = *region_node.as_table();
        const std::string region_path = path + ".region[" + std::to_string(r) + "]";
        const TableReader region_reader(region_table, region_path,
                                        context, line_of(region_node) > 0 ? line_of(region_node) : line);
        region_reader.check_keys(schema::table("region"));
        const std::string name = region_reader.optional_name("name").value_or(body.name + "_" + std::to_string(r));
        add_region_name(name, region_reader, "region");
        const auto amplitudes = take_boundary_amplitudes(region_table, region_path, context, region_reader.line(), problem);
        auto region = parse_region(region_table, region_path, context, region_reader.line(), name,
                                   schema::table("region"), schema::table("body.boundary"));
        set_load_groups(region, amplitudes);
        if (regions->size() > 1 && std::none_of(region.piece_interface.begin(), region.piece_interface.end(),
                                                [](const std::string& s) { return !s.empty(); }))
          region_reader.fail("boundary", "region '" + name + "' of body '" + body.name +
                                             "' has no boundary with interface = \"...\"; the regions of a body are "
                                             "bonded along shared interfaces");
        body.regions.push_back(std::move(region));
      }
    } else {
      reader.check_keys(schema::table("body"));
      add_region_name(body.name, reader, "body");
      const auto amplitudes = take_boundary_amplitudes(table, path, context, line, problem);
      auto region = parse_region(table, path, context, line, body.name, schema::table("body"),
                                 schema::table("body.boundary"));
      set_load_groups(region, amplitudes);
      for (std::size_t k = 0; k < region.piece_interface.size(); ++k)
        if (!region.piece_interface[k].empty())
          throw InputError(region.body.pieces[k].where,
                           "interface = \"" + region.piece_interface[k] + "\" bonds regions of one body; body '" +
                               body.name + "' has one region (write its regions as [[body.region]] tables)");
      body.regions.push_back(std::move(region));
    }
    problem.bodies.push_back(std::move(body));
  }
  const double extent = elastic_extent(problem);
  index = 0;
  for (toml::node& node : *bodies) {
    auto& body = problem.bodies[index++];
    const toml::table& table = *node.as_table();
    if (!table.contains("rigid")) continue;
    const std::string path = "body[" + std::to_string(index) + "]";
    const TableReader reader(table, path, context, line_of(node) > 0 ? line_of(node) : root.line());
    const toml::table* rigid = reader.optional_table("rigid", "[" + path + ".rigid]");
    if (!rigid) reader.fail("rigid", "must be a table: [body.rigid] with profile = ...");
    body.rigid = read_rigid(TableReader(*rigid, reader.key_path("rigid"), context, reader.line()), context, extent);
  }
  if (std::none_of(problem.bodies.begin(), problem.bodies.end(), [](const contact::Body& b) { return !b.rigid; }))
    root.fail("body", "every body is rigid; a contact problem needs at least one elastic body");
}

// A contact's law, its defaults applied here; and the tangential coupling (one for all
// contacts, checked by the caller).
// kind = "compliant": the compliance keys (NormalCompliance); refused with another kind.
void read_compliance(const TableReader& reader, contact::ContactLaw& law) {
  constexpr const char* keys[] = {"normal_stiffness", "normal_exponent", "friction_stiffness", "friction_exponent"};
  if (law.kind != contact::ContactKind::compliant) {
    for (const char* key : keys)
      if (reader.has(key))
        reader.fail(key, std::string(key) + " belongs to normal compliance: give kind = \"compliant\", or remove it");
    return;
  }
  if (!reader.has("normal_stiffness"))
    reader.fail("kind", "kind = \"compliant\" needs normal_stiffness (c_n: the pressure at a unit interpenetration)");
  auto& c = law.compliance;
  c.stiffness = *reader.optional_number("normal_stiffness");
  c.exponent = reader.optional_number("normal_exponent").value_or(1.0);
  c.friction_stiffness = reader.optional_number("friction_stiffness").value_or(c.stiffness);
  c.friction_exponent = reader.optional_number("friction_exponent").value_or(c.exponent);
  if (law.friction == 0.0)
    for (const char* key : {"friction_stiffness", "friction_exponent"})
      if (reader.has(key))
        reader.fail(key, std::string(key) + " sets the friction threshold; with friction = 0 it has no effect (remove "
                                            "it, or give a friction coefficient)");
}

contact::ContactLaw read_law(const TableReader& reader, bool& coupling) {
  contact::ContactLaw law;
  const std::string kind = reader.choice("kind");
  law.kind = kind == "bilateral"   ? contact::ContactKind::bilateral
             : kind == "compliant" ? contact::ContactKind::compliant
                                   : contact::ContactKind::unilateral;
  law.friction = reader.optional_number("friction").value_or(0.0);
  read_compliance(reader, law);
  law.nonlocal_radius = reader.optional_number("nonlocal_radius").value_or(0.0);
  if (reader.has("nonlocal_radius") && law.friction == 0.0)
    reader.fail("nonlocal_radius", "the non-local law mollifies the friction threshold; with friction = 0 it has no "
                                   "effect (remove it, or give a friction coefficient)");
  if (reader.has("nonlocal_radius") && law.kind == contact::ContactKind::compliant)
    reader.fail("nonlocal_radius", "the non-local law is not available with normal compliance yet (remove one of them)");
  law.wear_coefficient1 = reader.optional_number("wear_coefficient1").value_or(0.0);
  law.wear_coefficient2 = reader.optional_number("wear_coefficient2").value_or(0.0);
  coupling = reader.boolean_or("coupling", true);
  if (reader.has("coupling") && law.friction == 0.0)
    reader.fail("coupling", "'coupling' acts on the tangential tractions of friction; with friction = 0 it has "
                            "no effect (remove it, or give a friction coefficient)");
  return law;
}

void read_pairing(const TableReader& reader, contact::ContactInterface& contact) {
  contact.interference = reader.optional_number("interference").value_or(0.0);
  if (reader.has("interference_amplitude")) {
    if (contact.interference == 0.0)
      reader.fail("interference_amplitude", "the amplitude is that of the interference, which is not given");
    contact.interference_amplitude = read_amplitude(reader, "interference_amplitude");
  }
  if (const toml::node* gap = reader.find("gap")) {
    const auto value = read_prescribed_value(*gap, reader.where("gap"), reader.context());
    if (value.zero)
      reader.fail("gap", "the prescribed initial gap is zero everywhere: it would have no effect (remove it)");
    contact.initial_gap = value.field;
  }
  const std::string normal = reader.choice("normal");
  contact.pair_normal = normal == "body1"   ? contact::PairNormal::body1
                        : normal == "body2" ? contact::PairNormal::body2
                                            : contact::PairNormal::common;
  contact.pairing = reader.choice("pairing") == "mortar" ? contact::Pairing::mortar : contact::Pairing::node_to_segment;
}

// The non-local law's kernel runs along a plane boundary; axisymmetry would need its ring
// weights (not built yet).
void check_nonlocal_radius(const TableReader& reader, const contact::ContactInterface& contact,
                           const contact::ContactProblem& problem) {
  const double rho = contact.law.nonlocal_radius;
  if (!(rho > 0.0)) return;
  if (problem.analysis == AnalysisType::axisymmetric)
    reader.fail("nonlocal_radius", "the non-local friction law is available in plane problems only, not yet in "
                                   "axisymmetry");
  // A kernel wider than the zone mollifies the whole contact into one mean: not a law of the
  // pairs' neighbourhoods any more.
  const double length = contact::side_length(problem, contact.side1);
  if (rho > length)
    reader.fail("nonlocal_radius", "the radius " + format_number(rho) + " is larger than side 1's contact zone " +
                                       contact::side_text(problem, contact.side1) + " (length " + format_number(length) +
                                       "); the kernel should span a part of the contact, a tenth of its width say");
}

// A rigid body does not wear (its surface is the profile given).
void check_wear(const TableReader& reader, const contact::ContactInterface& contact,
                const contact::ContactProblem& problem) {
  const auto& side2 = problem.bodies.at(static_cast<std::size_t>(contact.side2.body));
  if (contact.law.wear_coefficient2 > 0.0 && side2.rigid)
    reader.fail("wear_coefficient2", "body '" + side2.name + "' is rigid: it does not wear (put the wear on side 1 "
                                     "with wear_coefficient1, or make body2 elastic)");
}

// An adaptive zone (contact_resolution) and its limits; the limits alone have no effect.
void read_zone_adaptivity(const TableReader& reader, contact::ContactInterface& contact) {
  auto& adaptivity = contact.adaptivity;
  adaptivity.resolution = reader.optional_number("contact_resolution").value_or(0.0);
  adaptivity.where = reader.where("contact_resolution");
  for (const char* key : {"max_adaptive_passes", "max_zone_elements"})
    if (reader.has(key) && !adaptivity.on())
      reader.fail(key, std::string(key) + " limits an adaptive zone, and contact_resolution is not given: it would "
                                          "have no effect (remove it, or give contact_resolution)");
  adaptivity.max_passes = reader.integer_or("max_adaptive_passes", adaptivity.max_passes);
  adaptivity.max_elements = reader.integer_or("max_zone_elements", adaptivity.max_elements);
  if (adaptivity.on() && contact.law.kind == contact::ContactKind::bilateral)
    reader.fail("contact_resolution", "a bilateral contact holds every pair closed: there is no zone to find (remove "
                                      "contact_resolution, or make the contact unilateral)");
}

void read_solver(const TableReader& reader, contact::ContactProblem& problem) {
  problem.operator_choice = read_operator_keys(reader);
  problem.increments = reader.integer_or("increments", problem.has_friction() ? 16 : 1);
  problem.record_steps = reader.boolean_or("record_steps", false);
  problem.record_steps_where = reader.where("record_steps");
  problem.adaptive = reader.boolean_or("adaptive", problem.has_friction());
  if (reader.has("adaptive") && problem.adaptive && !problem.has_friction())
    reader.fail("adaptive", "adaptive stepping follows the stick and slip zones; frictionless contact does not depend "
                            "on the load path, so it would have no effect (remove it, or give a friction coefficient)");
  problem.max_state_changes = reader.integer_or("max_state_changes", problem.max_state_changes);
  problem.max_steps = reader.integer_or("max_steps", std::max(problem.max_steps, problem.increments));
  if (problem.max_steps < problem.increments)
    reader.fail("max_steps", "must be >= increments (" + std::to_string(problem.increments) + ")");
  if (!problem.adaptive)
    for (const char* key : {"max_state_changes"})
      if (reader.has(key)) reader.fail(key, "'" + std::string(key) + "' tunes the adaptive stepping, which is off");
  problem.solver.algorithm = reader.choice("algorithm") == "thesis"
                                 ? contact::Algorithm::thesis
                                 : contact::Algorithm::newton;
  const std::string contact_operator = reader.choice("contact_operator");
  problem.solver.contact_operator = contact_operator == "dense"         ? contact::CondensedOperatorKind::dense
                                    : contact_operator == "matrix_free" ? contact::CondensedOperatorKind::matrix_free
                                                                        : contact::CondensedOperatorKind::automatic;
  if (reader.has("contact_operator")) problem.solver.contact_operator_where = reader.where("contact_operator");
  problem.solver.gmres_restart = reader.integer_or("gmres_restart", problem.solver.gmres_restart);
  problem.solver.max_gmres_cycles = reader.integer_or("max_gmres_cycles", problem.solver.max_gmres_cycles);
  problem.solver.xi = reader.optional_number("xi").value_or(problem.solver.xi);
  problem.solver.tolerance = reader.optional_number("tolerance").value_or(problem.solver.tolerance);
  problem.solver.tolerance_given = reader.has("tolerance");
  if (problem.solver.algorithm != contact::Algorithm::thesis)
    for (const char* thesis_key : {"gmres_restart", "max_gmres_cycles", "xi"})
      if (reader.has(thesis_key))
        reader.fail(thesis_key, "'" + std::string(thesis_key) +
                                    "' tunes the thesis algorithm only; it has no effect with algorithm = \"newton\" "
                                    "(remove it, or set algorithm = \"thesis\")");
  if (problem.solver.algorithm == contact::Algorithm::thesis && reader.has("tolerance"))
    reader.fail("tolerance", "'tolerance' is the Newton algorithm's; the thesis algorithm stops on xi (give xi "
                             "instead, or set algorithm = \"newton\")");
  problem.solver.max_iterations = reader.integer_or("max_iterations", problem.solver.max_iterations);
  if (problem.solver.algorithm == contact::Algorithm::thesis)
    for (const auto& contact : problem.contacts)
      if (contact.law.kind == contact::ContactKind::compliant)
        reader.fail("algorithm", "contact '" + contact.name + "' is compliant: normal compliance is solved by the "
                                 "Newton algorithm only (remove algorithm = \"thesis\")");
}

// A total force on a boundary of an elastic body (a rigid platen) or on a rigid body.
void read_force_load(const TableReader& load, contact::ContactProblem& problem) {
  load.check_keys(schema::table("load"));
  contact::ForceLoad force;
  const auto body_name = load.optional_string("body");
  if (!body_name) load.fail("body", "missing: the body that carries the force");
  force.body = body_named(problem, *body_name, load, "body");
  const auto& body = problem.bodies[force.body];
  if (body.rigid) {
    if (load.has("boundary"))
      load.fail("boundary", "body '" + *body_name + "' is rigid: the force acts on the whole body; remove 'boundary'");
  } else {
    const auto boundary = load.optional_string("boundary");
    if (!boundary) load.fail("boundary", "missing: the boundary that carries the force");
    const auto ref = boundary_named(problem, force.body, *boundary, load, "boundary");
    force.region = ref.region;
    force.piece = ref.pieces.front();
    for (const auto& contact : problem.contacts)
      for (const auto* side : {&contact.side1, &contact.side2})
        if (side->body == ref.body && side->holds(ref.region, force.piece))
          load.fail("boundary", "the force cannot act on a contact boundary itself");
    if (problem.region(ref).body.conditions[force.piece].signature != "free" &&
        problem.region(ref).body.conditions[force.piece].signature != "rigid platen")
      load.fail("boundary", "boundary '" + *boundary + "' of body '" + *body_name +
                                "' carries conditions, but a boundary under a force load moves as a rigid platen "
                                "(its displacement along the force is the unknown approach, the other component is "
                                "held at 0), so they would have no effect; remove them");
  }
  const int component = load.integer_or("component", 2);
  if (component < 1 || component > 3)
    load.fail("component", "must be 1 (x, or r in axisymmetry), 2 (y, or z) or 3 (the rotation of a rigid body)");
  if (component == 3) {
    if (body.rigid && body.rigid->rotation)
      load.fail("component", "rigid body '" + *body_name + "' has a prescribed rotation; a moment on it would leave "
                             "nothing to turn (give the rotation or the moment)");
    if (!body.rigid)
      load.fail("component", "component 3 (a moment) acts on a rigid body; body '" + *body_name + "' is elastic");
    if (problem.analysis == AnalysisType::axisymmetric)
      load.fail("component", "component 3 (a moment) has no meaning in axisymmetry (a rigid body there only translates "
                             "along the axis)");
    if (!body.rigid->reference)
      load.fail("component", "rigid body '" + *body_name + "' is a contour: it has no centre to rotate about (use a "
                             "profile with a center)");
  }
  // A prescribed translation moves a rigid body along its other components (a fretting
  // stroke along x under a normal force along y).
  if (body.rigid && body.rigid->displacement && component < 3 && (*body.rigid->displacement)[component - 1] != 0.0)
    load.fail("component", "rigid body '" + *body_name + "' has a prescribed displacement along this component; a "
                           "force along it would leave nothing to move (give that displacement component as 0, or "
                           "drop the force)");
  force.component = component - 1;
  force.force = load.number("force");
  if (force.force == 0.0) load.fail("force", "the total force must not be zero (a zero force through a "
                                                "history is given by its amplitude)");
  if (load.has("amplitude")) force.amplitude = read_amplitude(load, "amplitude");
  force.named = load.has("name");
  force.name = load.optional_name("name").value_or(body.name + (force.piece >= 0 ? "_" + body.regions[force.region].body.pieces[force.piece].name : std::string()) +
                                                    (force.component == 0 ? "_x" : force.component == 1 ? "_y" : "_rotation"));
  for (const auto& other : problem.forces) {
    if (other.name == force.name) load.fail("name", "two loads are named '" + force.name + "'");
    if (other.body == force.body && other.region == force.region && other.piece == force.piece &&
        other.component == force.component)
      load.fail("component", "a force in this direction on this " + std::string(force.piece >= 0 ? "boundary" : "body") +
                                 " is already given ('" + other.name + "')");
  }
  problem.forces.push_back(force);
}

// [load] or [[load]] at the top level.
void read_force_loads(const TableReader& root, FileContext& context, contact::ContactProblem& problem) {
  const toml::node* node = root.find("load");
  if (!node) return;
  if (const toml::table* table = node->as_table()) {
    read_force_load(TableReader(*table, "load", context, root.line()), problem);
    return;
  }
  const toml::array* list = node->as_array();
  if (!list || !list->is_array_of_tables()) root.fail("load", "must be a [load] table or [[load]] tables");
  int index = 0;
  for (const toml::node& entry : *list) {
    ++index;
    read_force_load(TableReader(*entry.as_table(), "load[" + std::to_string(index) + "]", context,
                                line_of(entry) > 0 ? line_of(entry) : root.line()),
                    problem);
  }
}

// The loads whose amplitude differs at t0 and t1 (by more than 1e-9 of its largest value),
// as "name (a at t0, b at t1)"; empty when every load agrees.
std::string loads_differing(const contact::ContactProblem& problem, double t0, double t1) {
  std::string out;
  const auto compare = [&](const std::string& name, const contact::Amplitude& a) {
    double scale = 1.0;
    for (const auto& p : a.points) scale = std::max(scale, std::abs(p.y()));
    const double v0 = a.at(t0), v1 = a.at(t1);
    if (std::abs(v1 - v0) <= 1e-9 * scale || !out.empty()) return;
    out = name + " (" + format_number(v0) + " at cycle_start, " + format_number(v1) + " at end_time)";
  };
  for (const auto& force : problem.forces) compare("load '" + force.name + "'", force.amplitude);
  for (const auto& body : problem.bodies)
    if (body.rigid) compare("the motion of rigid body '" + body.name + "'", body.rigid->amplitude);
  for (const auto& contact : problem.contacts)
    if (contact.interference != 0.0) compare("the interference of '" + contact.name + "'", contact.interference_amplitude);
  compare("data_amplitude", problem.data_amplitude);
  for (std::size_t g = 0; g < problem.boundary_amplitudes.size(); ++g)
    compare("a boundary's amplitude", problem.boundary_amplitudes[g]);
  return out;
}

// [history]'s repeated cycle (wear; contact_problem.hpp, LoadCycles): its keys have an
// effect only with cycles > 1 and a wearing contact, and the cycle must close.
void read_load_cycles(const TableReader& history, contact::ContactProblem& problem) {
  auto& cycles = problem.cycles;
  cycles.cycles = history.integer_or("cycles", 1);
  if (cycles.cycles == 1) {
    for (const char* key : {"cycle_start", "cycle_jump", "max_cycle_jump", "max_pressure_change"})
      if (history.has(key))
        history.fail(key, std::string(key) + " sets the repeated load cycles of a wear run; without cycles > 1 it "
                                             "has no effect");
    return;
  }
  if (!problem.has_wear())
    history.fail("cycles", "repeated load cycles serve the wear of a contact (wear_coefficient1 or 2 in a "
                           "[[contact]]); without wear every cycle is the same: remove cycles, or give a wear "
                           "coefficient");
  if (!history.has("cycle_start"))
    history.fail("cycles", "cycles > 1 needs cycle_start: the time where the repeated cycle starts (the history "
                           "from there to end_time is one load cycle)");
  cycles.start = *history.optional_number("cycle_start");
  if (!(cycles.start < problem.end_time))
    history.fail("cycle_start", "the cycle must start before end_time (" + format_number(problem.end_time) + ")");
  if (const std::string differing = loads_differing(problem, cycles.start, problem.end_time); !differing.empty())
    history.fail("cycle_start", "the cycle from " + format_number(cycles.start) + " to end_time " +
                                    format_number(problem.end_time) + " does not close: " + differing +
                                    "; a repeated cycle must end where it starts");
  // Every step of every computed cycle would be kept in memory and written (tens of
  // thousands): the wear outputs hold each computed cycle instead.
  if (problem.record_steps)
    throw InputError(problem.record_steps_where,
                     "record_steps would keep every step of every computed load cycle (cycles = " +
                         std::to_string(cycles.cycles) +
                         "); <contact>_wear_profile.csv and the wear/ series hold each computed cycle's pairs: "
                         "remove record_steps (or cycles)");
  cycles.fixed_jump = history.has("cycle_jump") ? history.integer_or("cycle_jump", 1) : 0;
  for (const char* key : {"max_cycle_jump", "max_pressure_change"})
    if (cycles.fixed_jump > 0 && history.has(key))
      history.fail(key, std::string(key) + " controls the adaptive jump; with a fixed cycle_jump it has no effect");
  cycles.max_jump = history.integer_or("max_cycle_jump", static_cast<int>(std::max(1L, cycles.cycles / 20)));
  cycles.max_pressure_change = history.optional_number("max_pressure_change").value_or(0.05);
}

// Every amplitude of the problem's loads (force loads, rigid bodies, interferences, boundary
// groups, the bodies' own data).
std::vector<const contact::Amplitude*> load_amplitudes(const contact::ContactProblem& problem) {
  std::vector<const contact::Amplitude*> out{&problem.data_amplitude};
  for (const auto& force : problem.forces) out.push_back(&force.amplitude);
  for (const auto& body : problem.bodies)
    if (body.rigid) out.push_back(&body.rigid->amplitude);
  for (const auto& contact : problem.contacts) out.push_back(&contact.interference_amplitude);
  for (const auto& amplitude : problem.boundary_amplitudes) out.push_back(&amplitude);
  return out;
}

// [history]: end_time and the amplitude of the bodies' own data.
void read_history(const TableReader& root, FileContext& context, contact::ContactProblem& problem) {
  const toml::table* table = root.optional_table("history", "[history]");
  std::optional<TableReader> history;
  if (table) {
    history.emplace(*table, "history", context, root.line());
    history->check_keys(schema::table("history"));
    if (history->has("data_amplitude")) problem.data_amplitude = read_amplitude(*history, "data_amplitude");
  }
  double last = 1.0;
  for (const auto* a : load_amplitudes(problem))
    if (!a->points.empty()) last = std::max(last, a->points.back().x());
  if (!history) {
    problem.end_time = last;
    return;
  }
  problem.end_time = history->optional_number("end_time").value_or(last);
  if (!(problem.end_time > 0.0 && std::isfinite(problem.end_time)))
    history->fail("end_time", "the end of the history must be a finite time > 0");
  // An end_time before an amplitude's last change cuts the history short (an unloading
  // left out): allowed, and said.
  const double end = problem.end_time;
  bool changes = false;
  for (const auto* a : load_amplitudes(problem))
    for (const Vec2& point : a->points)
      changes = changes || (point.x() > end && std::abs(point.y() - a->at(end)) > 1e-12 * std::abs(point.y()));
  if (changes)
    context.warnings.push_back(history->where("end_time").describe() + ": the history stops at end_time = " +
                               format_number(end) + ", but the amplitudes change until t = " + format_number(last) +
                               ": the loads after end_time are not run (the last step is the state at end_time)");
  read_load_cycles(*history, problem);
}

// Side `side` (1 or 2) of a contact from its body and boundary names.
// The boundary names of a side: one string, or a list of them (a chain).
std::vector<std::string> side_names(const TableReader& reader, const std::string& key) {
  const toml::node* node = reader.find(key);
  if (!node) return {};
  if (node->is_string()) return {*node->value<std::string>()};
  std::vector<std::string> names;
  for (const toml::node& item : *node->as_array()) names.push_back(*item.value<std::string>());  // checked: strings
  return names;
}

contact::BoundaryRef read_side(const TableReader& reader, const contact::ContactProblem& problem, int body, int side) {
  const std::string key = "boundary" + std::to_string(side);
  const auto& b = problem.bodies[body];
  if (b.rigid) {
    if (side == 1)
      reader.fail("body1", "body '" + b.name + "' is rigid; a rigid body must be the second side of a contact "
                                               "(body2), the elastic zone the first");
    if (reader.has(key))
      reader.fail(key, "body '" + b.name + "' is rigid: its whole profile is the contact surface; remove '" + key + "'");
    return {body, 0, {}};
  }
  const auto names = side_names(reader, key);
  if (names.empty()) reader.fail(key, "missing: name the boundary of body '" + b.name + "' in contact");
  contact::BoundaryRef out{body, 0, {}};
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& name = names[k];
    const auto ref = boundary_named(problem, body, name, reader, key);
    const int piece = ref.pieces.front();
    const auto& region = problem.region(ref);
    const auto& condition = region.body.conditions[piece];
    if (condition.kind[0] == bem::ConditionKind::displacement || condition.kind[1] == bem::ConditionKind::displacement ||
        condition.value[0] || condition.value[1] || !region.piece_interface[piece].empty())
      throw InputError(region.body.pieces[piece].where,
                       "boundary '" + name + "' of body '" + b.name + "' carries conditions (" + condition.signature +
                           ") but is in contact (" + reader.key_path(key) +
                           "); a contact boundary must have none: the contact sets them (remove them, or name another "
                           "boundary in the contact)");
    if (k == 0) {
      out.region = ref.region;
    } else {
      // A side is one zone: its boundaries of one region, each starting where the one before ends.
      if (ref.region != out.region)
        reader.fail(key, "boundaries '" + names[0] + "' and '" + name + "' of body '" + b.name +
                             "' lie in different regions; a side's boundaries must be of one region (one contact per "
                             "region)");
      if (out.holds(ref.region, piece)) reader.fail(key, "boundary '" + name + "' is named twice");
      const auto& before = region.body.pieces[out.pieces.back()];
      const auto& next = region.body.pieces[piece];
      const double size = std::max(geometry::piece_length(before), geometry::piece_length(next));
      if ((before.end - next.start).norm() > 1e-9 * size)
        reader.fail(key, "boundary '" + name + "' does not start where '" + names[k - 1] +
                             "' ends: list the side's boundaries joined end to start, in the order of travel along "
                             "the body's contour");
    }
    out.pieces.push_back(piece);
  }
  return out;
}

}  // namespace

ContactFile read_contact_file(const std::filesystem::path& path, const ParameterOverrides& overrides) {
  return parse_contact_problem(read_problem_text(path), path.string(), overrides);
}

ContactFile parse_contact_problem(std::string_view text, const std::string& file_name,
                                  const ParameterOverrides& overrides, const ResourceLimits& limits) {
  toml::table root_table = parse_toml_text(text, file_name);
  return parse_contact_table(root_table, file_name, overrides, limits);
}

// Bodies without contacts: each solved on its own (its bonds included); only the
// operator's keys of [solver] apply.
void read_without_contacts(const TableReader& root, FileContext& context, contact::ContactProblem& problem) {
  // Bodies without contacts: each solved on its own (its bonds included).
  // An elastoplastic region is solved in load steps: increments applies (10 by default).
  bool plastic = false;
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions) plastic = plastic || region.body.plasticity.has_value();
  if (plastic) problem.increments = 10;
  if (const toml::table* table = root.optional_table("solver", "[solver]")) {
    // Only the operator applies: the other keys set the contact solver.
    const TableReader solver(*table, "solver", context, root.line());
    for (const auto& key : schema::table("contact.solver").names())
      if (key != "operator" && key != "accuracy" && !(plastic && key == "increments") && solver.has(key))
        solver.fail(key, "'" + key + "' sets the contact solver; without [[contact]] tables it has no effect");
    solver.check_keys(schema::table("contact.solver"));
    problem.operator_choice = read_operator_keys(solver);
    problem.increments = solver.integer_or("increments", problem.increments);
  }
  read_force_loads(root, context, problem);
}

// The discontinuous elements' refusal. Measured on the Hertz ball: p0 +0.54 % against
// +0.02 % with continuous elements (the pairs sit at body 1's nodes, so discontinuous ones
// double them without a gain).
[[noreturn]] void refuse_discontinuous(const TableReader& root, FileContext& context) {
  const TableReader mesh(*root.optional_table("mesh", "[mesh]"), "mesh", context, root.line());
  mesh.fail("continuity", "discontinuous elements are not available in problems with contact pairs; remove "
                          "the key (continuous elements are the accurate choice for contact, docs/corners.md)");
}

// The thesis' single [contact] table: one contact between the two bodies, with its
// pairing, law, solver keys and [contact.load].
void read_single_contact(const TableReader& contact, const TableReader& root, FileContext& context,
                         contact::ContactProblem& problem, OutputNames& output_names) {
  contact.check_keys(schema::table("contact.single"));
  for (const char* key : {"solver", "load"})
    if (root.has(key))
      root.fail(key, "[" + std::string(key) + "] goes with [[contact]] tables; with a single [contact] table put " +
                         (std::string(key) == "load" ? "[contact.load]" : "the solver keys in [contact]"));
  if (problem.bodies.size() != 2)
    contact.fail("boundary1", "a [contact] table joins exactly two bodies; with " +
                                  std::to_string(problem.bodies.size()) +
                                  " bodies write one [[contact]] table per contact, with body1 and body2");
  contact::ContactInterface interface;
  output_names.claim(contact, contact_file_names(interface.name), "the contact");
  interface.side1 = read_side(contact, problem, 0, 1);
  interface.side2 = read_side(contact, problem, 1, 2);
  read_pairing(contact, interface);
  interface.law = read_law(contact, problem.tangential_coupling);
  check_nonlocal_radius(contact, interface, problem);
  check_wear(contact, interface, problem);
  read_zone_adaptivity(contact, interface);
  problem.contacts.push_back(interface);
  read_solver(contact, problem);
  if (const toml::table* load = contact.optional_table("load", "[contact.load]"))
    read_force_load(TableReader(*load, "contact.load", context, contact.line()), problem);
}

// [[contact]] tables, each with its sides, pairing and law; then [solver] and [[load]].
void read_contact_tables(const toml::node& contact_node, const TableReader& root, FileContext& context,
                         contact::ContactProblem& problem, OutputNames& output_names) {
  const toml::array* contacts = contact_node.as_array();
  if (!contacts || !contacts->is_array_of_tables() || contacts->empty())
    root.fail("contact", "must be a [contact] table or one or more [[contact]] tables");
  int index = 0;
  for (const toml::node& node : *contacts) {
    ++index;
    const std::string path = "contact[" + std::to_string(index) + "]";
    const TableReader contact(*node.as_table(), path, context, line_of(node) > 0 ? line_of(node) : root.line());
    contact.check_keys(schema::table("contact"));
    contact::ContactInterface interface;
    interface.name = contact.optional_name("name").value_or(contacts->size() == 1 ? "contact" : "contact" + std::to_string(index));
    for (const auto& other : problem.contacts)
      if (other.name == interface.name) contact.fail("name", "two contacts are named '" + interface.name + "'");
    output_names.claim(contact, contact_file_names(interface.name), "contact '" + interface.name + "'");
    for (const char* key : {"body1", "body2"})
      if (!contact.has(key)) contact.fail(key, "missing: the name of the body on this side of the contact");
    const int body1 = body_named(problem, *contact.optional_string("body1"), contact, "body1");
    const int body2 = body_named(problem, *contact.optional_string("body2"), contact, "body2");
    interface.side1 = read_side(contact, problem, body1, 1);
    interface.side2 = read_side(contact, problem, body2, 2);
    // Self-contact (a slot's or a crack's faces, a split ring): two boundaries of one body.
    if (body1 == body2)
      for (const int piece : interface.side2.pieces)
        if (interface.side1.holds(interface.side2.region, piece))
          contact.fail("boundary2", "a boundary cannot be in contact with itself; for self-contact name two "
                                    "boundaries of the body (split the boundary where the faces meet)");
    read_pairing(contact, interface);
    for (const auto& other : problem.contacts)
      for (const auto* side : {&other.side1, &other.side2})
        for (const auto* mine : {&interface.side1, &interface.side2})
          for (const int piece : mine->pieces)
            if (side->body == mine->body && side->holds(mine->region, piece))
              contact.fail("boundary1", "a boundary is in two contacts ('" + other.name + "' and '" + interface.name +
                                          "'); split it into two boundaries");
    // Each contact its own law (kind, friction). The tangential coupling shapes the
    // condensed operator: one for every contact.
    bool coupling = true;
    interface.law = read_law(contact, coupling);
    check_nonlocal_radius(contact, interface, problem);
    check_wear(contact, interface, problem);
    read_zone_adaptivity(contact, interface);
    if (index == 1) problem.tangential_coupling = coupling;
    problem.contacts.push_back(interface);
    if (index > 1 && coupling != problem.tangential_coupling)
      contact.fail("coupling", "every contact must have the same tangential coupling as the first (it is a property "
                               "of the condensed operator); kind and friction may differ per contact");
  }
  static const toml::table empty;
  const toml::table* solver = root.optional_table("solver", "[solver]");
  const TableReader solver_keys_reader(solver ? *solver : empty, "solver", context, root.line());
  solver_keys_reader.check_keys(schema::table("contact.solver"));
  read_solver(solver_keys_reader, problem);
  read_force_loads(root, context, problem);
}

// A rigid body needs a motion (prescribed, or a force's), a contact, and no rotation in
// axisymmetry.
void check_rigid_bodies(const contact::ContactProblem& problem) {
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const auto& body = problem.bodies[b];
    if (!body.rigid) continue;
    const bool loaded = std::any_of(problem.forces.begin(), problem.forces.end(),
                                    [b](const contact::ForceLoad& f) { return f.body == static_cast<int>(b); });
    if (body.rigid->rotation && problem.analysis == AnalysisType::axisymmetric)
      throw InputError(body.where, "rigid body '" + body.name + "': a rotation has no meaning in axisymmetry (a rigid "
                                   "body there only translates along the axis)");
    if (!loaded && !body.rigid->displacement && !body.rigid->rotation)
      throw InputError(body.where, "rigid body '" + body.name + "' has no load and no displacement: give its displacement in "
                        "[body.rigid] (displacement = [u1, u2]) or press it with a force ([load] body = \"" + body.name +
                        "\")");
    bool in_contact = false;
    for (const auto& contact : problem.contacts) in_contact = in_contact || contact.side2.body == static_cast<int>(b);
    if (!in_contact) throw InputError(body.where, "rigid body '" + body.name + "' is in no contact: it would have no effect");
  }
}

// contact_operator = "matrix_free" where its step solver does not serve the model.
void check_contact_operator(const contact::ContactProblem& problem) {
  if (problem.solver.contact_operator != contact::CondensedOperatorKind::matrix_free) return;
  const std::string obstacle = contact::matrix_free_obstacle(problem);
  if (!obstacle.empty())
    throw InputError(problem.solver.contact_operator_where,
                     "the condensed operator cannot be applied matrix-free: " + obstacle +
                         " (remove contact_operator, or set it to \"dense\")");
}

ContactFile parse_contact_table(toml::table& root_table, const std::string& file_name,
                                const ParameterOverrides& overrides, const ResourceLimits& limits) {
  ContactFile result;
  FileContext context = FileContext::starting(file_name, overrides, limits);
  const TableReader root(root_table, "", context, 1);
  root.check_keys(schema::table("contact.file"));
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
    reader.check_keys(schema::table("output"));
    result.vtk = reader.boolean_or("vtk", true);
  }
  OutputNames output_names;
  read_bodies(root_table, root, context, problem, output_names);
  check_gmsh_overrides(root, context, result.parameters);

  const toml::node* contact_node = root.find("contact");
  // Where pairing errors point: the table that declared the contacts.
  std::string pairing_key = "body";
  const TableReader* anchor = &root;
  std::optional<TableReader> single;
  if (!contact_node) {
    read_without_contacts(root, context, problem);
  } else if (problem.mesh.discontinuous) {
    refuse_discontinuous(root, context);
  } else if (const toml::table* table = contact_node->as_table()) {
    single.emplace(*table, "contact", context, root.line());
    read_single_contact(*single, root, context, problem, output_names);
    anchor = &*single;
    pairing_key = "boundary1";
  } else {
    read_contact_tables(*contact_node, root, context, problem, output_names);
    pairing_key = "contact";
  }
  read_history(root, context, problem);
  check_rigid_bodies(problem);
  check_contact_operator(problem);
  // Pair the zones now, so that geometric errors point at the contact tables (those about
  // a body's own boundaries point at them).
  try {
    (void)contact::prepare_contact(problem);
  } catch (const GeometryError& error) {
    if (!error.where().empty()) throw;
    throw InputError(anchor->where(pairing_key), error.what());
  }
  result.warnings = context.warnings;
  return result;
}

}  // namespace bemcontact::io
