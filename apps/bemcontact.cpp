// bemcontact: command line. Arguments -> problem file -> solve -> writers.
#include <omp.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <nlohmann/json.hpp>

#include "bemcontact/core/error.hpp"
#include "bemcontact/driver/probe.hpp"
#include "bemcontact/driver/run.hpp"
#include "bemcontact/io/output/output_directory.hpp"
#include "bemcontact/io/input/problem_schema.hpp"
#include "bemcontact/io/input/problem_text.hpp"
#include "bemcontact/operators/dense_lu.hpp"
#include "bemcontact/validation/validation.hpp"
#ifdef BEMCONTACT_WITH_MPI
#include "bemcontact/parallel/session.hpp"
#endif

#ifndef BEMCONTACT_EXAMPLES_DIR
#define BEMCONTACT_EXAMPLES_DIR "examples"
#endif

namespace {

using namespace bemcontact;
using nlohmann::json;

enum ExitCode { ok = 0, validation_failed = 1, bad_input = 2, solver_failed = 3, internal = 4 };

// Progress on stderr, only when it is a terminal and not silenced.
bem::ProgressCallback make_progress(bool quiet) {
  if (quiet || !isatty(STDERR_FILENO)) return {};
  return [last = std::string(), last_percent = -1](const std::string& phase, double fraction) mutable {
    const int percent = static_cast<int>(fraction * 100.0);
    if (phase == last && percent == last_percent) return;
    last = phase;
    last_percent = percent;
    std::fprintf(stderr, "\r%-20s %3d %%%s", phase.c_str(), percent, percent >= 100 ? "\n" : "");
    std::fflush(stderr);
  };
}

// The folder's own files by name; those of its sub-folders (recorded load steps: a few
// per step) counted.
void print_written(const std::string& output_dir, const io::OutputDirectory& out) {
  std::vector<std::string> names;
  std::map<std::string, int> in_folder;
  for (const auto& name : out.names()) {
    const auto slash = name.find('/');
    if (slash == std::string::npos) names.push_back(name);
    else ++in_folder[name.substr(0, slash)];
  }
  constexpr std::size_t kListed = 24;
  std::printf("  wrote %s/{", output_dir.c_str());
  for (std::size_t k = 0; k < names.size() && k < kListed; ++k) std::printf("%s%s", k ? "," : "", names[k].c_str());
  if (names.size() > kListed) std::printf(",... %zu files in all", names.size());
  std::printf("}\n");
  for (const auto& [folder, count] : in_folder)
    std::printf("  wrote %d file%s into %s/%s/\n", count, count == 1 ? "" : "s", output_dir.c_str(), folder.c_str());
}

// `run` and `mesh`: the driver computes every file in memory, then the folder is replaced
// whole (io/output_directory.hpp).
int command_run(const std::string& input, const std::string& output_dir, bool quiet, driver::RunOptions options,
                bool mesh_only) {
  const std::string text = io::read_problem_text(input);
  // Under mpirun every process solves its share; the root alone prints and writes.
  const bool root = options.parallel.distribution.root();
  if (root) io::check_output_directory(output_dir);  // refused now rather than after the solve
  quiet = quiet || !root;
  options.progress = make_progress(quiet);
  if (!quiet && !mesh_only)
    options.notice = [](const std::string& line) {
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
    };
  const auto output = mesh_only ? driver::mesh_problem(text, input, options) : driver::run_problem(text, input, options);
  if (!root) return output.solver_failure.empty() ? ok : solver_failed;
  for (const auto& warning : output.warnings) std::fprintf(stderr, "bemcontact: warning: %s\n", warning.c_str());
  output.files.commit(output_dir);
  if (!output.solver_failure.empty()) {
    std::fprintf(stderr, "bemcontact: solver error: %s (diagnostics in %s)\n", output.solver_failure.c_str(),
                 output_dir.c_str());
    return solver_failed;
  }
  if (!quiet) {
    std::printf("%s", output.report.c_str());
    print_written(output_dir, output.files);
  }
  return ok;
}

// A file's whole text, or nothing when it is missing or unreadable.
std::optional<std::string> file_text(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) return std::nullopt;
  return text.str();
}

// `probe`: values at new points of a finished run, from the files of its folder; the
// probe's files replace the folder `output_dir` whole (default RUN_DIR/probe).
int command_probe(const std::string& run_dir, const std::string& points_file, const std::vector<std::string>& lines,
                  std::string output_dir, bool quiet, const ResourceLimits& limits) {
  if (!std::filesystem::is_directory(run_dir))
    throw InputError(SourceLocation{run_dir, 0, ""}, "no such run folder (bemcontact run FILE -o DIR writes one)");
  if (output_dir.empty()) output_dir = (std::filesystem::path(run_dir) / "probe").string();
  {
    // The probe's folder replaces -o whole: the run folder itself, or a folder holding it,
    // would lose the run.
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path run = fs::weakly_canonical(fs::absolute(run_dir), error);
    const fs::path out = fs::weakly_canonical(fs::absolute(output_dir), error);
    const auto [end, at] = std::mismatch(out.begin(), out.end(), run.begin(), run.end());
    if (!error && end == out.end())
      throw InputError(SourceLocation{"command line", 0, "-o"},
                       "the probe's folder '" + output_dir + "' is the run folder '" + run_dir +
                           "' or holds it, and would replace it (and the run) whole: give another folder, or leave "
                           "-o out for RUN_DIR/probe");
  }
  io::check_output_directory(output_dir);  // refused now rather than after the probe
  driver::ProbeRequest request;
  if (!points_file.empty()) {
    request.points_file = points_file;
    const auto text = file_text(points_file);
    if (!text)
      throw InputError(SourceLocation{points_file, 0, ""}, "cannot read the points file (missing, a folder or unreadable)");
    request.listed = io::parse_points_file(*text, points_file);
  }
  for (const auto& line : lines) request.lines.push_back(io::parse_probe_line(line));
  driver::ProbeOptions options;
  options.run_name = run_dir;
  options.read_input = [](const std::string& path) { return file_text(path); };
  options.progress = make_progress(quiet);
  options.limits = limits;
  const auto output = driver::probe_run(
      [&](const std::string& name) { return file_text(std::filesystem::path(run_dir) / name); }, request, options);
  for (const auto& warning : output.warnings) std::fprintf(stderr, "bemcontact: warning: %s\n", warning.c_str());
  output.files.commit(output_dir);
  if (!quiet) {
    std::printf("%s", output.report.c_str());
    print_written(output_dir, output.files);
  }
  return ok;
}

// `plot` and `validate --report` draw with the Python package (matplotlib), which keeps
// the C++ core free of plotting: the command hands over to its interpreter.
int run_python_module(const std::string& module, std::vector<std::string> arguments) {
#if defined(BEMCONTACT_PYTHON) && defined(BEMCONTACT_PYTHON_DIR)
  std::string path = BEMCONTACT_PYTHON_DIR;
  if (const char* extra = std::getenv("BEMCONTACT_PYTHONPATH")) path = std::string(extra) + ":" + path;
  if (const char* existing = std::getenv("PYTHONPATH")) path += std::string(":") + existing;
  ::setenv("PYTHONPATH", path.c_str(), 1);
  arguments.insert(arguments.begin(), {BEMCONTACT_PYTHON, "-m", module});
  std::vector<char*> argv;
  for (auto& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  pid_t child = 0;
  const int error = ::posix_spawn(&child, BEMCONTACT_PYTHON, nullptr, nullptr, argv.data(), environ);
  if (error != 0) {
    std::fprintf(stderr, "bemcontact: cannot start %s: %s\n", BEMCONTACT_PYTHON, std::strerror(error));
    return internal;
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : internal;
#else
  (void)arguments;
  std::fprintf(stderr, "bemcontact: %s needs the Python module, and this build has none "
                       "(configure with -DBEMCONTACT_BUILD_PYTHON=ON and pybind11-dev, python3-numpy, "
                       "python3-matplotlib installed)\n", module.c_str());
  return bad_input;
#endif
}

std::string params_text(const validation::Record& r) {
  std::string text;
  for (const auto& [key, value] : r.params) text += (text.empty() ? "" : " ") + key + "=" + value;
  return text;
}

int command_validate(std::vector<std::string> names, const std::vector<std::string>& skip, const std::string& json_path,
                     const validation::Context& context, bool list) {
  const auto& all = validation::cases();
  if (list) {
    for (const auto& c : all) std::printf("%-26s %-8s %s\n", c.name.c_str(), c.section.c_str(), c.description.c_str());
    return ok;
  }
  if (names.empty())
    for (const auto& c : all)
      if (std::find(skip.begin(), skip.end(), c.name) == skip.end()) names.push_back(c.name);
  std::vector<const validation::Case*> selected;
  for (const auto& name : names) {
    const validation::Case* found = nullptr;
    for (const auto& c : all)
      if (c.name == name) found = &c;
    if (!found) {
      std::string valid;
      for (const auto& c : all) valid += (valid.empty() ? "" : ", ") + c.name;
      std::fprintf(stderr, "bemcontact validate: unknown case '%s'; valid cases: %s\n", name.c_str(), valid.c_str());
      return bad_input;
    }
    selected.push_back(found);
  }
  json records = json::array();
  int failed = 0, total = 0;
  std::printf("%-24s %-34s %-22s %14s %14s %10s %10s  %s\n", "case", "params", "quantity", "computed", "reference",
              "error", "tolerance", "pass");
  for (const auto* c : selected) {
    std::vector<validation::Record> results;
    try {
      results = c->run(context);
    } catch (const std::exception& e) {
      std::printf("%-24s failed to run: %s\n", c->name.c_str(), e.what());
      ++failed;
      ++total;
      records.push_back({{"case", c->name}, {"params", json::object()}, {"quantity", "run"},
                         {"computed", nullptr}, {"reference", nullptr}, {"tolerance", nullptr},
                         {"passed", false}, {"message", e.what()}});
      continue;
    }
    if (context.operator_kind != bem::OperatorKind::automatic)
      for (auto& r : results)
        if (std::none_of(r.params.begin(), r.params.end(), [](const auto& p) { return p.first == "operator"; })) {
          r.params.emplace_back("operator", bem::to_string(context.operator_kind));
          if (context.operator_accuracy > 0.0) r.params.emplace_back("accuracy", validation::number_text(context.operator_accuracy));
        }
    for (const auto& r : results) {
      const bool counted = r.comparison != validation::Comparison::report;
      total += counted;
      failed += counted && !r.passed;
      // A value reported without a reference shows "-" for reference and error.
      auto cell = [](double value, int width) {
        char text[64];
        if (std::isnan(value)) std::snprintf(text, sizeof text, "%*s", width, "-");
        else std::snprintf(text, sizeof text, "%*.*g", width, width == 14 ? 6 : 3, value);
        return std::string(text);
      };
      std::printf("%-24s %-34s %-22s %14.6g %s %s %10.3g  %s\n", r.case_name.c_str(), params_text(r).c_str(),
                  r.quantity.c_str(), r.computed, cell(r.reference, 14).c_str(), cell(r.error, 10).c_str(), r.tolerance,
                  !counted ? "info" : r.passed ? "yes" : "NO");
      json params = json::object();
      for (const auto& [key, value] : r.params) params[key] = value;
      const char* comparison = r.comparison == validation::Comparison::relative ? "relative"
                               : r.comparison == validation::Comparison::scaled ? "scaled"
                               : r.comparison == validation::Comparison::at_least ? "at_least"
                                                                                  : "report";
      records.push_back({{"case", r.case_name}, {"params", params}, {"quantity", r.quantity},
                         {"computed", r.computed}, {"reference", r.reference}, {"error", r.error},
                         {"comparison", comparison}, {"tolerance", counted ? json(r.tolerance) : json(nullptr)},
                         {"passed", counted ? json(r.passed) : json(nullptr)}});
    }
  }
  std::printf("validate: %d passed, %d failed\n", total - failed, failed);
  if (!json_path.empty()) {
    io::write_file_atomically(json_path, records.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
  }
  return failed == 0 ? ok : validation_failed;
}

}  // namespace

// A global option written after the sub-command (`run FILE --threads 2`): where it goes.
std::string global_option_hint(int argc, char** argv) {
  bool after_command = false;
  for (int k = 1; k < argc; ++k) {
    const std::string word = argv[k];
    if (word == "run" || word == "mesh" || word == "validate" || word == "plot" || word == "probe")
      after_command = true;
    else if (after_command && (word == "--threads" || word.rfind("--threads=", 0) == 0))
      return "bemcontact: --threads is a global option: write it before the sub-command, e.g. "
             "bemcontact --threads 2 run FILE";
  }
  return {};
}

// `bemcontact keys`: the schema's tables (problem_schema.hpp); --write-docs regenerates
// docs/keys.md and the key tables of the other pages.
int command_keys(const std::vector<std::string>& ids, const std::string& docs_dir) {
  if (!docs_dir.empty()) {
    namespace fs = std::filesystem;
    auto write_if_changed = [](const fs::path& path, const std::string& text) {
      std::ifstream in(path);
      std::stringstream old;
      old << in.rdbuf();
      if (in && old.str() == text) return;
      std::ofstream(path) << text;
      std::printf("wrote %s\n", path.string().c_str());
    };
    write_if_changed(fs::path(docs_dir) / "keys.md", io::schema::reference_markdown());
    std::vector<fs::path> pages;
    for (const auto& entry : fs::directory_iterator(docs_dir))
      if (entry.path().extension() == ".md" && entry.path().filename() != "keys.md") pages.push_back(entry.path());
    std::sort(pages.begin(), pages.end());
    for (const auto& page : pages) {
      std::ifstream in(page);
      std::stringstream text;
      text << in.rdbuf();
      try {
        write_if_changed(page, io::schema::with_key_tables(text.str()));
      } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "bemcontact keys: %s: %s\n", page.string().c_str(), e.what());
        return bad_input;
      }
    }
    return ok;
  }
  if (ids.empty()) {
    for (const auto& table : io::schema::tables()) std::printf("%-20s %s\n", table.id.c_str(), table.title.c_str());
    return ok;
  }
  for (const auto& id : ids) {
    const io::schema::Table* found = nullptr;
    for (const auto& table : io::schema::tables())
      if (table.id == id) found = &table;
    if (!found) {
      std::fprintf(stderr, "bemcontact keys: no table '%s' (bemcontact keys lists them)\n", id.c_str());
      return bad_input;
    }
    std::printf("%s (%s)\n\n%s\n\n", found->title.c_str(), found->id.c_str(), io::schema::markdown(*found).c_str());
  }
  return ok;
}

// A value that must be > 0 (CLI11's PositiveNumber says "not in range 0 to 1.8e308" of 0).
const CLI::Validator kPositive(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || !(value > 0.0))
        return "must be a number > 0, found '" + text + "'";
      return {};
    },
    "NUMBER > 0");

int main(int argc, char** argv) {
  CLI::App app{"bemcontact: boundary elements for 2D and axisymmetric elasticity and frictional contact"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("bemcontact ") + BEMCONTACT_VERSION);
  int threads = 0;
  app.add_option("--threads", threads, "number of threads (default: OMP_NUM_THREADS or all cores)")
      ->check(kPositive);

  std::string input, output_dir = "out";
  bool quiet = false;
  std::vector<std::string> assignments;
  driver::RunOptions run_options;
  double max_memory_gb = 0.0;
  const auto add_run_options = [&](CLI::App* command, const char* quiet_help) {
    command->add_option("FILE", input, "problem file (TOML)")->required();
    command->add_option("-o,--output", output_dir, "output directory, replaced whole (default: out)");
    command->add_flag("-q,--quiet", quiet, quiet_help);
    command->add_option("--set", assignments, "NAME=VALUE: replace a [parameters] value of the file (repeatable)");
    command->add_option("--max-elements", run_options.limits.max_elements,
                        "largest number of elements of one body (default 200000)")
        ->check(kPositive);
    command->add_option("--max-points", run_options.limits.max_interior_points,
                        "largest number of interior points (default 2000000)")
        ->check(kPositive);
    command->add_option("--max-memory", max_memory_gb,
                        "memory the dense systems may take, in GB (default: 80 % of the machine's)")
        ->check(kPositive);
    command->add_option("--gmsh-timeout", run_options.limits.gmsh_timeout_seconds,
                        "seconds Gmsh may take to mesh a .geo file (default 60)")
        ->check(kPositive);
  };
  auto* run = app.add_subcommand("run", "solve a problem file and write boundary.csv, interior.csv, VTK, summary.json");
  add_run_options(run, "no progress and no summary on the terminal");
  auto* mesh = app.add_subcommand("mesh", "write the boundary mesh only (nodes, elements, normals)");
  add_run_options(mesh, "print nothing");

  std::vector<std::string> cases, skip;
  std::string json_path, examples = BEMCONTACT_EXAMPLES_DIR;
  bool list = false;
  auto* validate = app.add_subcommand("validate", "run the built-in reference cases against closed-form solutions");
  validate->add_option("CASE", cases, "cases to run (default: all; --list shows them)");
  validate->add_option("--json", json_path, "write the records as JSON to this file");
  validate->add_option("--examples", examples, "folder of the bundled example problems");
  validate->add_flag("--list", list, "list the cases");
  validate->add_option("--skip", skip, "cases to leave out of a full run");
  validate->add_flag("-q,--quiet", quiet, "no progress");
  std::string validate_operator = "auto";
  validate->add_option("--operator", validate_operator,
                       "the operator of every problem whose case leaves it to auto: auto, dense or compressed "
                       "(the records then carry params.operator)")
      ->check(CLI::IsMember({"auto", "dense", "compressed"}));
  double validate_accuracy = 0.0;
  auto* accuracy_option =
      validate->add_option("--accuracy", validate_accuracy,
                           "with --operator compressed: the compressed operator's accuracy (default: each problem's, automatic)")
          ->check(CLI::Range(1e-14, 1e-2));
  std::string report_dir;
  validate->add_option("--report", report_dir, "write an HTML page with the table and one figure per case to this folder");

  std::string plot_source, plot_output, plot_format = "png";
  auto* plot = app.add_subcommand("plot", "figures of a problem file (mesh) or of a run's output folder (mesh, "
                                          "stresses, contact tractions, load history)");
  plot->add_option("SOURCE", plot_source, "problem file or output folder")->required();
  plot->add_option("-o,--output", plot_output, "folder of the figures (default: SOURCE/figures or STEM_figures)");
  plot->add_option("--format", plot_format, "png or svg")->check(CLI::IsMember({"png", "svg"}));

  std::vector<std::string> key_tables;
  std::string docs_dir;
  auto* keys = app.add_subcommand("keys", "the keys of each table of a problem file: type, default, meaning "
                                          "(docs/keys.md); without ID, the tables");
  keys->add_option("ID", key_tables, "a table's id (e.g. boundary, contact, contact.solver)");
  keys->add_option("--write-docs", docs_dir, "regenerate DIR/keys.md and the key tables of DIR/*.md");
  std::string probe_run_dir, probe_points, probe_output;
  std::vector<std::string> probe_lines;
  ResourceLimits probe_limits;
  auto* probe = app.add_subcommand("probe", "displacements and stresses at new points of a finished run, from its "
                                            "boundary solution (no new solve): probe.csv, probe.vtk, probe.json");
  probe->add_option("OUTPUT_DIR", probe_run_dir, "the output folder of a run")->required();
  probe->add_option("--points", probe_points, "CSV file of points x,y (one per line; a header allowed)");
  probe->add_option("--line", probe_lines, "x0,y0,x1,y1,n: n points from (x0, y0) to (x1, y1), ends included "
                                           "(repeatable)")
      ->allow_extra_args(false);  // one line per --line: a word after it is OUTPUT_DIR
  probe->add_option("-o,--output", probe_output,
                    "folder of the probe's files, replaced whole (default: OUTPUT_DIR/probe)");
  probe->add_flag("-q,--quiet", quiet, "print nothing but warnings and errors");
  probe->add_option("--max-points", probe_limits.max_interior_points, "largest number of points (default 2000000)")
      ->check(kPositive);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    if (const std::string hint = global_option_hint(argc, argv); !hint.empty()) std::cerr << hint << "\n";
    return bad_input;  // every command-line error is bad input (exit 2)
  }
  if (threads > 0) omp_set_num_threads(threads);
  operators::use_single_threaded_blas();
#ifdef BEMCONTACT_WITH_MPI
  const parallel::MpiSession session;
  run_options.parallel = session.decomposition_run();
  const bool distributed = session.size() > 1;
  // Input and geometry errors arise alike on every process (each reads the whole file): the
  // root reports them. A failure on one process ends all of them (the others would wait for
  // it in the next sum).
  const auto report_on_root = [&](auto&& print) {
    if (session.rank() == 0) print();
  };
  const auto end_all = [&](int code) {
    if (distributed) session.abort(code);
    return code;
  };
#else
  const bool distributed = false;
  const auto report_on_root = [](auto&& print) { print(); };
  const auto end_all = [](int code) { return code; };
#endif
  try {
    if (distributed && !*run)
      throw InputError(SourceLocation{input, 0, ""}, "only `run` works on several processes (mpirun -n N); run `" +
                                             std::string(*mesh       ? "mesh"
                                                         : *validate ? "validate"
                                                         : *probe    ? "probe"
                                                         : *keys     ? "keys"
                                                                     : "plot") +
                                             "` on one process");
    for (const auto& assignment : assignments) io::add_parameter_override(run_options.overrides, assignment);
    run_options.limits.max_memory_bytes = max_memory_gb * 1e9;
    if (*keys) return command_keys(key_tables, docs_dir);
    if (*run) return command_run(input, output_dir, quiet, run_options, false);
    if (*mesh) return command_run(input, output_dir, quiet, run_options, true);
    if (*probe) input = probe_run_dir;  // geometry errors name the run's folder
    if (*probe) return command_probe(probe_run_dir, probe_points, probe_lines, probe_output, quiet, probe_limits);
    if (*validate) {
      if (!report_dir.empty() && json_path.empty()) json_path = (std::filesystem::path(report_dir) / "validate.json").string();
      if (!report_dir.empty()) std::filesystem::create_directories(report_dir);
      const auto kind = validate_operator == "dense"        ? bem::OperatorKind::dense
                        : validate_operator == "compressed" ? bem::OperatorKind::compressed
                                                            : bem::OperatorKind::automatic;
      if (accuracy_option->count() > 0 && kind != bem::OperatorKind::compressed)
      {
        std::fprintf(stderr, "bemcontact validate: --accuracy sets the compressed operator; give it with --operator "
                             "compressed\n");
        return bad_input;
      }
      const validation::Context context{examples, make_progress(quiet), kind, validate_accuracy};
      const int code = command_validate(cases, skip, json_path, context, list);
      if (report_dir.empty() || list) return code;
      const int drawn = run_python_module("bemcontact.report", {json_path, report_dir});
      return code != ok ? code : drawn;
    }
    if (*plot) {
      std::vector<std::string> arguments{plot_source, "--format", plot_format};
      if (!plot_output.empty()) arguments.insert(arguments.end(), {"-o", plot_output});
      return run_python_module("bemcontact.plot", arguments);
    }
  } catch (const InputError& e) {
    report_on_root([&] { std::fprintf(stderr, "bemcontact: error: %s\n", e.what()); });
    return bad_input;
  } catch (const GeometryError& e) {
    // An error placed at its boundaries starts with their file and line.
    report_on_root([&] {
      if (e.where().empty()) std::fprintf(stderr, "bemcontact: geometry error in %s: %s\n", input.c_str(), e.what());
      else std::fprintf(stderr, "bemcontact: geometry error: %s\n", e.what());
    });
    return bad_input;
  } catch (const SolverError& e) {
    std::fprintf(stderr, "bemcontact: solver error: %s\n", e.what());
    return end_all(solver_failed);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bemcontact: error: %s\n", e.what());
    return end_all(internal);
  }
  return ok;
}
