// The bemcontact command as a user runs it: exit codes, messages, whole-or-nothing outputs.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <csignal>
#include <map>
#include <set>
#include <sstream>
#include <unistd.h>

#include "bemcontact/io/input/gmsh_geometry.hpp"

namespace fs = std::filesystem;

namespace {

struct Outcome {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

Outcome run(const std::string& arguments) {
  const std::string command = std::string(BEMCONTACT_BINARY) + " " + arguments + " 2>&1";
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("bemcontact_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string example(const std::string& name) { return std::string(BEMCONTACT_SOURCE_DIR) + "/examples/" + name; }

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string example_text(const std::string& name) {
  std::ifstream in(example(name));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const char* free_body = R"(analysis = "plane_strain"
[material]
E = 1000.0
nu = 0.3
[vertices]
A = [0.0, 0.0]
B = [1.0, 0.0]
C = [1.0, 1.0]
D = [0.0, 1.0]
[[boundary]]
from = "A"
to = "B"
elements = 2
[[boundary]]
from = "B"
to = "C"
elements = 2
t1 = 1.0
[[boundary]]
from = "C"
to = "D"
elements = 2
[[boundary]]
from = "D"
to = "A"
elements = 2
t1 = -1.0
)";

}  // namespace

TEST(CommandLine, RunWritesEveryOutputAndASummary) {
  const auto dir = scratch("run");
  const auto out = run("run " + example("plate_tension.toml") + " -o " + (dir / "out").string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  for (const char* name : {"boundary.csv", "interior.csv", "boundary.vtk", "interior.vtk", "summary.json"})
    EXPECT_TRUE(fs::exists(dir / "out" / name)) << name;
  std::ifstream in(dir / "out" / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["analysis"], "plane_stress");
  EXPECT_EQ(summary["options"]["mesh"]["interpolation"], "linear");
  EXPECT_EQ(summary["mesh"]["elements"], 16);
  EXPECT_LT(summary["results"]["solve"]["relative_residual"].get<double>(), 1e-12);
  EXPECT_TRUE(summary["timings_seconds"].contains("assembly"));
  EXPECT_TRUE(summary["timings_seconds"].contains("solve"));
  // The estimate, printed before the result and kept in the summary.
  EXPECT_LT(out.output.find("estimate: 40 unknowns"), out.output.find("time ")) << out.output;
  EXPECT_EQ(summary["estimate"]["unknowns"], 2 * summary["mesh"]["nodes"].get<int>());
  fs::remove_all(dir);
}

TEST(CommandLine, ProblemFileErrorsNameFileLineAndKeyWithExitCode2) {
  const auto dir = scratch("bad");
  std::string text = free_body;
  text.replace(text.find("nu = 0.3"), 8, "nuu = 0.3");
  write(dir / "typo.toml", text);
  const auto out = run("run " + (dir / "typo.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("typo.toml:4"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("nuu"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("nu"), std::string::npos) << out.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  const auto missing = run("run " + (dir / "nothing.toml").string());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("nothing.toml"), std::string::npos) << missing.output;
  fs::remove_all(dir);
}

TEST(CommandLine, AFreeBodyIsASolverErrorAndWritesNothing) {
  const auto dir = scratch("free");
  write(dir / "free.toml", free_body);
  const auto out = run("run " + (dir / "free.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 3) << out.output;
  EXPECT_NE(out.output.find("rigid body"), std::string::npos) << out.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

TEST(CommandLine, AFolderOfSomeoneElsesFilesIsRefusedBeforeTheSolve) {
  // The folder's state is known before the run: refused then, not after a long solve.
  const auto dir = scratch("foreign");
  fs::create_directories(dir / "out");
  write(dir / "out" / "thesis.tex", "precious\n");
  const auto out = run("run " + example("plate_hole.toml") + " -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 4) << out.output;
  EXPECT_NE(out.output.find("did not write"), std::string::npos) << out.output;
  EXPECT_EQ(out.output.find("estimate"), std::string::npos) << "solved before refusing:\n" << out.output;
  EXPECT_EQ(fs::directory_iterator(dir / "out")->path().filename(), "thesis.tex");
  fs::remove_all(dir);
}

TEST(CommandLine, GeometryErrorsNameTheBoundary) {
  const auto dir = scratch("geometry");
  std::string text = free_body;
  text.replace(text.find("D = [0.0, 1.0]"), 14, "D = [0.0, 1.0]\nE = [0.2, 1.0]");
  text.replace(text.rfind("from = \"D\""), 10, "from = \"E\"");
  write(dir / "open.toml", text);
  const auto out = run("run " + (dir / "open.toml").string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("open contour"), std::string::npos) << out.output;
  // Placed at the boundary: "geometry error: FILE:LINE: key 'boundary[k]': ...".
  EXPECT_NE(out.output.find("geometry error: " + (dir / "open.toml").string() + ":"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find(": key 'boundary["), std::string::npos) << out.output;
  fs::remove_all(dir);
}

TEST(CommandLine, MeshWritesNodesElementsAndVtk) {
  const auto dir = scratch("mesh");
  const auto out = run("mesh " + example("plate_hole.toml") + " -o " + dir.string() + " -q");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_TRUE(fs::exists(dir / "mesh_nodes.csv"));
  EXPECT_TRUE(fs::exists(dir / "mesh_elements.csv"));
  EXPECT_TRUE(fs::exists(dir / "mesh.vtk"));
  fs::remove_all(dir);
}

TEST(CommandLine, MeshAcceptsEveryKindOfProblem) {
  // Bodies, regions and contacts: each region's mesh and each contact's pairs.
  const auto dir = scratch("mesh_models");
  auto out = run("mesh " + example("contact_roller_plates.toml") + " -o " + (dir / "roller").string() + " -q");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  for (const char* name : {"roller_mesh_nodes.csv", "top_plate_mesh.vtk", "bottom_pairs.csv", "top_pairs.csv"})
    EXPECT_TRUE(fs::exists(dir / "roller" / name)) << name;
  out = run("mesh " + example("dd_strips_2.toml") + " -o " + (dir / "dd").string() + " -q");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_TRUE(fs::exists(dir / "dd" / "strip1_mesh_elements.csv"));
  fs::remove_all(dir);
}

TEST(CommandLine, RunSolvesBodiesWithoutContact) {
  // The unified format with two bonded regions and no contact.
  const auto dir = scratch("bonded");
  fs::create_directories(dir);
  std::ofstream(dir / "bonded.toml") << R"(analysis = "plane_strain"
[[body]]
name = "block"
[[body.region]]
name = "upper"
material = { E = 2.0, nu = 0.3 }
vertices = { A = [0.0, 0.0], B = [1.0, 0.0], C = [1.0, 1.0], D = [0.0, 1.0] }
boundary = [ { name = "bond", from = "A", to = "B", elements = 6, interface = "i" },
             { name = "right", from = "B", to = "C", elements = 6 },
             { name = "top", from = "C", to = "D", elements = 6, t2 = -1.0 },
             { name = "left", from = "D", to = "A", elements = 6 } ]
[[body.region]]
name = "lower"
material = { E = 1.0, nu = 0.3 }
vertices = { A = [0.0, -1.0], B = [1.0, -1.0], C = [1.0, 0.0], D = [0.0, 0.0] }
boundary = [ { name = "base", from = "A", to = "B", elements = 6, u1 = 0.0, u2 = 0.0 },
             { name = "right", from = "B", to = "C", elements = 6 },
             { name = "bond", from = "C", to = "D", elements = 6, interface = "i" },
             { name = "left", from = "D", to = "A", elements = 6 } ]
)";
  const auto out = run("run " + (dir / "bonded.toml").string() + " -o " + (dir / "out").string() + " -q");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  for (const char* name : {"upper_boundary.csv", "lower_boundary.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(dir / "out" / name)) << name;
  std::ifstream in(dir / "out" / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  // The base carries the top's load: F_y = 1 per unit width (to the nodal integration).
  double base = 0.0;
  for (const auto& entry : summary["reactions"]["lower"])
    if (entry["boundary"] == "base") base = entry["force"][1].get<double>();
  EXPECT_NEAR(base, 1.0, 5e-3);
  // One body of regions and nothing else: the model takes the decomposition, whatever the spelling.
  EXPECT_EQ(summary["kind"], "decomposition");
  EXPECT_TRUE(fs::exists(dir / "out" / "interface.csv"));
  fs::remove_all(dir);
}

// A [[body]] of one region alone is solved directly, as the one-body spelling of the same
// body is (the same numbers), and keeps the body's name in its file names.
TEST(CommandLine, TheModelNotTheSpellingChoosesTheSolver) {
  const auto dir = scratch("route");
  std::string one_body = example_text("plate_tension.toml");
  write(dir / "one.toml", one_body);
  ASSERT_EQ(run("run " + (dir / "one.toml").string() + " -o " + (dir / "one").string() + " -q").exit_code, 0);
  // The same body as a [[body]] table: the root's body keys moved under [[body]].
  std::string body = one_body;
  for (const std::string table : {"material", "vertices", "interior"})
    for (std::size_t at = body.find("[" + table + "]"); at != std::string::npos; at = body.find("[" + table + "]", at + 1))
      body.replace(at, table.size() + 2, "[body." + table + "]");
  for (std::size_t at = body.find("[[boundary]]"); at != std::string::npos; at = body.find("[[boundary]]", at + 1))
    body.replace(at, 12, "[[body.boundary]]");
  for (std::size_t at = body.find("[[constraint]]"); at != std::string::npos; at = body.find("[[constraint]]", at + 1))
    body.replace(at, 14, "[[body.constraint]]");
  body.insert(body.find("[body.material]"), "[[body]]\nname = \"plate\"\n");
  write(dir / "bodies.toml", body);
  const auto out = run("run " + (dir / "bodies.toml").string() + " -o " + (dir / "bodies").string() + " -q");
  ASSERT_EQ(out.exit_code, 0) << out.output << body;
  std::ifstream in(dir / "bodies" / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(in)["kind"], "body");
  std::ifstream a(dir / "one" / "boundary.csv"), b(dir / "bodies" / "plate_boundary.csv");
  std::stringstream text_a, text_b;
  text_a << a.rdbuf();
  text_b << b.rdbuf();
  EXPECT_FALSE(text_a.str().empty());
  EXPECT_EQ(text_a.str(), text_b.str());
  fs::remove_all(dir);
}

TEST(CommandLine, KeysPrintsTheSchema) {
  const auto list = run("keys");
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.output.find("contact.solver"), std::string::npos) << list.output;
  const auto material = run("keys material");
  EXPECT_EQ(material.exit_code, 0);
  EXPECT_NE(material.output.find("| `nu` | number in (-1, 0.5) | required | Poisson's ratio |"), std::string::npos)
      << material.output;
  const auto unknown = run("keys nothing");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.output.find("no table 'nothing'"), std::string::npos) << unknown.output;
}

TEST(CommandLine, ValidateRejectsAnUnknownCaseListingTheValidOnes) {
  const auto out = run("validate no-such-case");
  EXPECT_EQ(out.exit_code, 2);
  EXPECT_NE(out.output.find("plate-tension"), std::string::npos) << out.output;
}

TEST(CommandLine, ValidateWritesJsonRecordsWithTheDocumentedKeys) {
  const auto dir = scratch("validate");
  const auto out = run("validate plate-tension -q --json " + (dir / "records.json").string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  std::ifstream in(dir / "records.json");
  const auto records = nlohmann::json::parse(in);
  ASSERT_GT(records.size(), 5u);
  for (const char* key : {"case", "params", "quantity", "computed", "reference", "tolerance", "passed"})
    EXPECT_TRUE(records[0].contains(key)) << key;
  EXPECT_EQ(records[0]["case"], "plate-tension");
  EXPECT_EQ(records[0]["params"]["interpolation"], "linear");
  fs::remove_all(dir);
}

// --operator compressed tags the records of the cases it applies to; --accuracy alone (no
// compressed operator to set) is refused.
TEST(CommandLine, ValidateOnTheCompressedOperatorTagsItsRecords) {
  const auto dir = scratch("validate-compressed");
  const auto out =
      run("validate thick-cylinder -q --operator compressed --accuracy 1e-12 --json " + (dir / "records.json").string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  std::ifstream in(dir / "records.json");
  const auto records = nlohmann::json::parse(in);
  ASSERT_GT(records.size(), 0u);
  for (const auto& record : records) {
    EXPECT_EQ(record["params"]["operator"], "compressed");
    EXPECT_EQ(record["params"]["accuracy"], "1e-12");
  }
  EXPECT_EQ(run("validate thick-cylinder --accuracy 1e-12").exit_code, 2);
  EXPECT_EQ(run("validate thick-cylinder --operator sparse").exit_code, 2);
  fs::remove_all(dir);
}

TEST(CommandLine, RunSolvesADecompositionFile) {
  const auto dir = scratch("dd");
  const auto out = run("run " + example("dd_strips_2.toml") + " -o " + dir.string() + " -q");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  for (const char* name : {"interface.csv", "gmres.csv", "summary.json"}) EXPECT_TRUE(fs::exists(dir / name)) << name;
  std::ifstream in(dir / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["results"]["decomposition"]["gmres"]["status"], "converged");
  fs::remove_all(dir);
}

TEST(CommandLine, CommandLineErrorsExitWith2) {
  // Before the sub-command, a missing file argument, an unknown option, a bad number.
  for (const std::string arguments :
       {"run --threads 2 " + example("plate_tension.toml"), std::string("run"), std::string("run --no-such-option x.toml"),
        "--threads zero run " + example("plate_tension.toml"), std::string("no-such-command")}) {
    const auto out = run(arguments);
    EXPECT_EQ(out.exit_code, 2) << arguments << "\n" << out.output;
  }
  EXPECT_EQ(run("--version").exit_code, 0);
  EXPECT_EQ(run("--help").exit_code, 0);
  // A global option after the sub-command says where it goes.
  const auto late = run("run " + example("plate_tension.toml") + " --threads 2");
  EXPECT_EQ(late.exit_code, 2);
  EXPECT_NE(late.output.find("--threads is a global option: write it before the sub-command"), std::string::npos)
      << late.output;
}

TEST(CommandLine, LimitsAreInputErrorsThatSayHowToRaiseThem) {
  const fs::path dir = scratch("limits");
  const auto out = run("run " + example("plate_tension.toml") + " --max-elements 10 -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("--max-elements"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("plate_tension.toml:"), std::string::npos) << out.output;
  const auto memory = run("run " + example("plate_tension.toml") + " --max-memory 0.000001 -o " + (dir / "out").string());
  EXPECT_EQ(memory.exit_code, 2) << memory.output;
  EXPECT_NE(memory.output.find("--max-memory"), std::string::npos) << memory.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CommandLine, AnArcOfMoreThanHalfATurnIsAWarningNamingIt) {
  const fs::path dir = scratch("arc_warning");
  std::string problem = example_text("plate_hole.toml");
  const auto at = problem.find("direction = \"cw\"");
  ASSERT_NE(at, std::string::npos);
  problem.replace(at, 16, "direction = \"ccw\"");
  write(dir / "lobe.toml", problem);
  const auto out = run("mesh " + (dir / "lobe.toml").string() + " -q -o " + (dir / "out").string());
  EXPECT_NE(out.output.find("warning"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("sweeping 270 degrees"), std::string::npos) << out.output;
}

// Every output byte is the same for --threads 1 and 2 and for any OpenBLAS thread count.
TEST(CommandLine, OutputsAreIdenticalForEveryThreadSetting) {
  const fs::path dir = scratch("threads");
  for (const char* name : {"plate_hole.toml", "dd_strips_3.toml", "contact_flat_punch.toml"}) {
    std::map<std::string, std::string> reference;
    bool first = true;
    for (const std::string setting : {"OPENBLAS_NUM_THREADS=1 ", "OPENBLAS_NUM_THREADS=2 "})
      for (const std::string threads : {"1", "2"}) {
        const fs::path out = dir / ("out" + threads);
        const std::string command = "env " + setting + BEMCONTACT_BINARY + " --threads " + threads + " run " +
                                    example(name) + " -q -o " + out.string() + " 2>&1";
        ASSERT_EQ(std::system(command.c_str()), 0) << command;
        std::map<std::string, std::string> files;
        for (const auto& entry : fs::directory_iterator(out)) {
          const std::string file = entry.path().filename().string();
          if (file == "summary.json") continue;  // holds timings and the thread count
          std::ifstream in(entry.path(), std::ios::binary);
          std::stringstream content;
          content << in.rdbuf();
          files[file] = content.str();
        }
        if (first) reference = files, first = false;
        else EXPECT_TRUE(files == reference) << name << " differs with " << setting << "--threads " << threads;
      }
  }
}

// SIGINT or SIGTERM at any moment leaves the output folder as it was before the run or
// as the run made it, never a mix, and no staging folder behind.
TEST(CommandLine, SignalsNeverLeaveAHalfWrittenFolder) {
  const fs::path dir = scratch("signals");
  const fs::path out = dir / "out";
  ASSERT_EQ(run("run " + example("thick_ring_plane_strain.toml") + " -q -o " + out.string()).exit_code, 0);
  std::set<std::string> complete;
  for (const auto& entry : fs::directory_iterator(out)) complete.insert(entry.path().filename().string());
  for (int trial = 0; trial < 24; ++trial) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const std::string input = example(trial % 2 ? "thick_ring_plane_strain.toml" : "plate_hole.toml");
      execl(BEMCONTACT_BINARY, BEMCONTACT_BINARY, "run", input.c_str(), "-q", "-o", out.c_str(), nullptr);
      _exit(127);
    }
    usleep(2000 * trial);  // 0 to 46 ms: before, during and after the commit
    kill(child, trial % 3 ? SIGINT : SIGTERM);
    int status = 0;
    waitpid(child, &status, 0);
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(out)) names.insert(entry.path().filename().string());
    EXPECT_TRUE(names.count(".bemcontact-output") && names.count("summary.json") && names.count("boundary.csv"))
        << "trial " << trial;
    for (const auto& entry : fs::directory_iterator(dir))
      EXPECT_EQ(entry.path().filename().string(), "out") << "left behind: " << entry.path();
  }
}

TEST(CommandLine, APointFarOutsideTheBodyIsAnInputErrorNamingItsLine) {
  const fs::path dir = scratch("far_point");
  std::string problem = example_text("plate_tension.toml");
  const auto at = problem.find("points = [");
  ASSERT_NE(at, std::string::npos);
  problem.insert(at + 10, "[1e200, 0.5], ");
  write(dir / "far.toml", problem);
  const auto out = run("run " + (dir / "far.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("(1e+200, 0.5) is not inside the body"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("far.toml:"), std::string::npos) << out.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CommandLine, AListedPointOutsideABodyOfAContactFileIsAnInputError) {
  // As in a one-body file (grid points outside a body are dropped and listed, not errors).
  const fs::path dir = scratch("contact_point");
  std::string problem = example_text("contact_hertz_sphere.toml");
  const auto at = problem.find("[body.interior]");
  ASSERT_NE(at, std::string::npos);
  problem.insert(problem.find('\n', at) + 1, "points = [[0.05, 0.5]]\n");
  write(dir / "ball.toml", problem);
  const auto out = run("run " + (dir / "ball.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("(0.05, 0.5) is not inside body 'support'"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("ball.toml:"), std::string::npos) << out.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CommandLine, DisplacementsBeyondSmallStrainsAreAWarning) {
  // E in GPa with loads in MPa: the plate stretches by half its size; the run still answers.
  const fs::path dir = scratch("units");
  std::string problem = example_text("plate_tension.toml");
  const auto at = problem.find("E = 100000.0");
  ASSERT_NE(at, std::string::npos);
  problem.replace(at, 12, "E = 2.0");
  write(dir / "gpa.toml", problem);
  const auto out = run("run " + (dir / "gpa.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find("of its size"), std::string::npos) << out.output;
  EXPECT_NE(out.output.find("linear elasticity assumes small strains"), std::string::npos) << out.output;
  const auto plain = run("run " + example("plate_tension.toml") + " -o " + (dir / "plain").string());
  EXPECT_EQ(plain.output.find("small strains"), std::string::npos) << plain.output;
}

// Gmsh meshes in a child process: the run keeps its --threads, and a .geo that does not end
// stops at --gmsh-timeout naming the file.
TEST(CommandLine, GeoRunsKeepTheirThreadsAndStopAtTheTimeout) {
  if (!bemcontact::io::gmsh_api_available()) GTEST_SKIP() << "built without the Gmsh library (.geo files refused)";
  const auto dir = scratch("geo");
  const auto out = run("--threads 2 run " + example("gmsh_plate_hole.toml") + " -q -o " + (dir / "out").string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  std::ifstream in(dir / "out" / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(in).at("options").at("threads"), 2);
  write(dir / "endless.geo", "Point(1) = {0, 0, 0};\nFor i In {1:1e15}\nEndFor\n");
  write(dir / "endless.toml", "analysis = \"plane_stress\"\ngeometry = \"endless.geo\"\n[material]\nE = 1.0\nnu = 0.3\n");
  const auto stopped = run("run " + (dir / "endless.toml").string() + " --gmsh-timeout 0.2 -o " + (dir / "out2").string());
  EXPECT_EQ(stopped.exit_code, 2) << stopped.output;
  EXPECT_NE(stopped.output.find("endless.toml:2: key 'geometry': " + (dir / "endless.geo").string() +
                                ": Gmsh did not finish meshing the file within 0.2 s (--gmsh-timeout)"),
            std::string::npos)
      << stopped.output;
  fs::remove_all(dir);
}

std::string file_content(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CommandLine, ProbeWritesItsFilesIntoTheRunFolderOrOneGiven) {
  const fs::path dir = scratch("probe");
  const auto out = run("run " + example("plate_tension.toml") + " -o " + (dir / "out").string());
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_EQ(file_content(dir / "out" / "problem.toml"), example_text("plate_tension.toml"));
  write(dir / "pts.csv", "x,y\n0,0.5\n0.5,1.5\n");
  const auto probed = run("probe " + (dir / "out").string() + " --points " + (dir / "pts.csv").string() +
                          " --line -1,1,1,1,5 --line 0,0,0,2,3");
  ASSERT_EQ(probed.exit_code, 0) << probed.output;
  EXPECT_NE(probed.output.find("10 points: 10 rows"), std::string::npos) << probed.output;
  for (const char* name : {"probe.csv", "probe.vtk", "probe.json", ".bemcontact-output"})
    EXPECT_TRUE(fs::exists(dir / "out" / "probe" / name)) << name;
  std::ifstream in(dir / "out" / "probe" / "probe.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["rows"], 10);
  EXPECT_EQ(summary["lines"].size(), 2u);
  const auto elsewhere = run("probe " + (dir / "out").string() + " --line -1,1,1,1,3 -q -o " + (dir / "section").string());
  EXPECT_EQ(elsewhere.exit_code, 0) << elsewhere.output;
  EXPECT_EQ(elsewhere.output, "");
  EXPECT_TRUE(fs::exists(dir / "section" / "probe.csv"));
  // A later run into the folder replaces the probe with the rest.
  ASSERT_EQ(run("run " + example("plate_tension.toml") + " -q -o " + (dir / "out").string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "out" / "probe"));
  fs::remove_all(dir);
}

TEST(CommandLine, ProbeErrorsAreBadInputAndWriteNothing) {
  const fs::path dir = scratch("probe_errors");
  const auto missing = run("probe " + (dir / "nothing").string() + " --line 0,0,1,1,3");
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("nothing: no such run folder"), std::string::npos) << missing.output;
  write(dir / "plate.toml", example_text("plate_tension.toml"));
  ASSERT_EQ(run("run " + (dir / "plate.toml").string() + " -q -o " + (dir / "out").string()).exit_code, 0);
  const std::string folder = (dir / "out").string();
  const auto no_points = run("probe " + folder);
  EXPECT_EQ(no_points.exit_code, 2) << no_points.output;
  EXPECT_NE(no_points.output.find("give points: --points FILE or --line"), std::string::npos) << no_points.output;
  const auto no_file = run("probe " + folder + " --points " + (dir / "none.csv").string());
  EXPECT_EQ(no_file.exit_code, 2) << no_file.output;
  EXPECT_NE(no_file.output.find("none.csv"), std::string::npos) << no_file.output;
  write(dir / "bad.csv", "x,y\n0,1\n0,one\n");
  const auto bad = run("probe " + folder + " --points " + (dir / "bad.csv").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("bad.csv:3: y = 'one' is not a finite number"), std::string::npos) << bad.output;
  write(dir / "far.csv", "0,1\n7,1\n");
  const auto far = run("probe " + folder + " --points " + (dir / "far.csv").string());
  EXPECT_EQ(far.exit_code, 2) << far.output;
  EXPECT_NE(far.output.find("far.csv:2: point (7, 1) lies inside no body"), std::string::npos) << far.output;
  const auto bad_line = run("probe " + folder + " --line 0,0,1,1");
  EXPECT_EQ(bad_line.exit_code, 2) << bad_line.output;
  EXPECT_NE(bad_line.output.find("--line 0,0,1,1"), std::string::npos) << bad_line.output;
  // -o the run folder itself, or a folder holding it: the probe's folder would replace the run.
  for (const fs::path& target : {dir / "out", dir}) {
    const auto over = run("probe " + folder + " --line -1,1,1,1,3 -o " + target.string());
    EXPECT_EQ(over.exit_code, 2) << over.output;
    EXPECT_NE(over.output.find("would replace it (and the run) whole"), std::string::npos) << over.output;
  }
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
  const auto huge = run("probe " + folder + " --line -1,1,1,1,900000000");  // counted, not made
  EXPECT_EQ(huge.exit_code, 2) << huge.output;
  EXPECT_NE(huge.output.find("over the limit"), std::string::npos) << huge.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "probe"));
  // A run folder without problem.toml (older) whose input file changed since.
  fs::remove(dir / "out" / "problem.toml");
  ASSERT_EQ(run("probe " + folder + " --line -1,1,1,1,3 -q").exit_code, 0);
  write(dir / "plate.toml", example_text("plate_tension.toml") + "\n# edited\n");
  const auto changed = run("probe " + folder + " --line -1,1,1,1,3");
  EXPECT_EQ(changed.exit_code, 2) << changed.output;
  EXPECT_NE(changed.output.find("plate.toml' changed since the run"), std::string::npos) << changed.output;
  fs::remove_all(dir);
}

// A rigid contour from a CSV file whose x turns back: exit code 2, the message names the CSV
// file, its line and the problem file's key.
TEST(CommandLine, BadProfileFileIsAnInputError) {
  const auto dir = scratch("profile");
  std::string text = example_text("contact_rough_profile.toml");
  const auto from = text.find("profile = \"rough\""), to = text.find("[[contact]]");
  ASSERT_NE(from, std::string::npos);
  text.replace(from, to - from, "profile = \"contour\"\npoints_file = \"measured.csv\"\n\n");
  write(dir / "rough.toml", text);
  write(dir / "measured.csv", "x,y\n-2.0,0.01\n0.0,0.0\n-1.0,0.01\n2.0,0.01\n");
  const auto out = run("run " + (dir / "rough.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find((dir / "measured.csv").string() + ":4: key 'body[2].rigid.points_file'"), std::string::npos)
      << out.output;
  write(dir / "measured.csv", "x,y\n-2.0,0.01\n0.0,0.0\n2.0,0.01\n");
  EXPECT_EQ(run("run " + (dir / "rough.toml").string() + " -o " + (dir / "out").string() + " -q").exit_code, 0);
  fs::remove_all(dir);
}
