// Bad contact problem files -> clear messages naming the file, line, key, boundary or body.
#include <gtest/gtest.h>

#include "../unit/contact/contact_fixtures.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <sstream>

#include "bemcontact/io/input/problem_text.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "support/contact_input.hpp"
#include "support/example_text.hpp"

namespace bemcontact {
namespace {

std::string example_text() { return test_support::example_text("contact_hertz_sphere.toml"); }
using test_support::replaced;

std::string input_error(const std::string& text) { return test_support::contact_input_error(text, "ball.toml"); }

// The message of the solver error the problem raises (a failure when it solves).
std::string solver_error(const contact::ContactProblem& problem) {
  try {
    contact::solve_contact(problem);
  } catch (const SolverError& error) {
    return error.what();
  }
  ADD_FAILURE() << "a free body was solved";
  return "no error";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(ContactErrors, ExampleIsAContactFile) {
  EXPECT_EQ(io::problem_kind(example_text()), io::ProblemKind::contact);
  EXPECT_EQ(io::problem_kind("analysis = \"plane_strain\"\n"), io::ProblemKind::body);
  EXPECT_NO_THROW(io::parse_contact_problem(example_text(), "ball.toml"));
}

TEST(ContactErrors, BoundariesThatDoNotFaceEachOther) {
  // The ball's side arc as its contact boundary, paired along its own normals: they pass
  // beside the support's contact zone (a zone larger than the contact is fine).
  const auto message = input_error(replaced(replaced(example_text(), "boundary1 = \"contact\"", "boundary1 = \"arc\""),
                                            "normal = \"body2\"", "normal = \"body1\""));
  EXPECT_TRUE(contains(message, "ball.toml:")) << message;
  EXPECT_TRUE(contains(message, "do not face each other")) << message;
  EXPECT_TRUE(contains(message, "boundary 'contact' of body 'support'")) << message;
}

TEST(ContactErrors, DiscontinuousElementsAreRefusedWithContactPairs) {
  const auto message = input_error(example_text() + "\n[mesh]\ncontinuity = \"discontinuous\"\n");
  EXPECT_TRUE(contains(message, "ball.toml:")) << message;
  EXPECT_TRUE(contains(message, "key 'mesh.continuity'")) << message;
  EXPECT_TRUE(contains(message, "not available in problems with contact pairs")) << message;
}

TEST(ContactErrors, NegativeInterferenceNamesTheKey) {
  const auto message = input_error(replaced(example_text(), "increments = 1", "increments = 1\ninterference = -0.01"));
  EXPECT_TRUE(contains(message, "key 'contact.interference'")) << message;
  EXPECT_TRUE(contains(message, ">= 0")) << message;
}

TEST(ContactErrors, InitiallyOverlappingBodies) {
  auto text = replaced(example_text(), "S = [0.0, 0.0]", "S = [0.0, -0.001]");
  text = replaced(text, "Q = [\"rc\", \"R - R*cos(theta)\"]", "Q = [\"rc\", \"R - R*cos(theta) - 0.001\"]");
  text = replaced(text, "E = [\"R\", \"R\"]", "E = [\"R\", \"R - 0.001\"]");
  text = replaced(text, "N = [0.0, \"R\"]", "N = [0.0, \"R - 0.001\"]");
  text = replaced(text, "O = [0.0, \"R\"]", "O = [0.0, \"R - 0.001\"]");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "overlap")) << message;
}

TEST(ContactErrors, UnknownContactBoundaryListsTheBoundaries) {
  const auto message = input_error(replaced(example_text(), "boundary2 = \"contact\"", "boundary2 = \"contakt\""));
  EXPECT_TRUE(contains(message, "contact.boundary2")) << message;
  EXPECT_TRUE(contains(message, "'base'")) << message;
}

TEST(ContactErrors, ContactBoundaryWithConditions) {
  const auto message = input_error(replaced(example_text(), "name = \"contact\"\nfrom = \"D\"\nto = \"F\"\n",
                                            "name = \"contact\"\nfrom = \"D\"\nto = \"F\"\nu2 = 0.0\n"));
  EXPECT_TRUE(contains(message, "carries conditions")) << message;
  EXPECT_TRUE(contains(message, "key 'body[2].boundary[4]'")) << message;  // the boundary, not the contact table
  EXPECT_TRUE(contains(message, "u2=0")) << message;
}

TEST(ContactErrors, NegativeFrictionAndBadIncrements) {
  EXPECT_TRUE(contains(input_error(replaced(example_text(), "friction = 0.0", "friction = -0.1")), "contact.friction"));
  EXPECT_TRUE(contains(input_error(replaced(example_text(), "increments = 1", "increments = 0")), "contact.increments"));
}

TEST(ContactErrors, ForceOnAnUnknownBody) {
  const auto message = input_error(replaced(example_text(), "body = \"ball\"", "body = \"bal\""));
  EXPECT_TRUE(contains(message, "contact.load.body")) << message;
}

TEST(ContactErrors, FreeBodyNamesTheBodyAndTheMotion) {
  // A cylinder on a block (plane strain) with its top set free and no force: only the
  // frictionless contact holds it, and its normals are all but vertical, so the horizontal
  // translation and the rotation are free.
  auto problem = contact::testing::cylinder_on_block(1.0, 0.25, 10, 1.0, {1.0, 0.3}, {1.0, 0.3});
  problem.forces.clear();
  problem.elastic(0).conditions[2] = {};
  const std::string message = solver_error(problem);
  EXPECT_TRUE(contains(message, "body 'cylinder' is free to move")) << message;
  EXPECT_TRUE(contains(message, "translation x") || contains(message, "rotation")) << message;
}

TEST(ContactErrors, BodyHeldOnlyByItsContactIsSolved) {
  // The axisymmetric ball with its top free and no force: its axial translation is held by
  // the contact (pair normals along z), so it is an unknown with the ball's equilibrium;
  // with no load the answer is no contact force.
  auto file = io::parse_contact_problem(example_text(), "ball.toml");
  file.problem.forces.clear();
  file.problem.elastic(0).conditions[2] = {};
  const auto result = contact::solve_contact(file.problem);
  EXPECT_NEAR(result.summary.normal_force, 0.0, 1e-9);
}

}  // namespace bemcontact

namespace bemcontact {

// Keys that would have no effect where they stand are refused, naming the key.
TEST(ContactErrors, KeysWithoutEffectAreRefused) {
  const std::string text = example_text();
  std::string message = input_error(replaced(text, "increments = 1", "increments = 1\ngmres_restart = 2"));
  EXPECT_TRUE(contains(message, "key 'contact.gmres_restart'") && contains(message, "thesis algorithm only")) << message;
  message = input_error(replaced(text, "increments = 1", "increments = 1\nalgorithm = \"thesis\"\ntolerance = 1e-8"));
  EXPECT_TRUE(contains(message, "key 'contact.tolerance'")) << message;
  message = input_error(replaced(text, "increments = 1", "increments = 1\ncoupling = false"));
  EXPECT_TRUE(contains(message, "key 'contact.coupling'") && contains(message, "friction = 0")) << message;
  // The platen under [contact.load] takes no condition of its own.
  message = input_error(replaced(text, "to = \"N\"\nelements = 6\n", "to = \"N\"\nelements = 6\nu1 = 0.0\n"));
  EXPECT_TRUE(contains(message, "key 'contact.load.boundary'") && contains(message, "rigid platen")) << message;
  message = input_error(replaced(text, "increments = 1", "increments = 1000000"));
  EXPECT_TRUE(contains(message, "over the limit")) << message;
}

}  // namespace bemcontact

namespace bemcontact {
namespace {

std::string example(const std::string& name) { return test_support::example_text(name); }

}  // namespace

// The [[contact]] spelling: bodies of regions, rigid bodies, several contacts.
TEST(ContactErrors, UnifiedExamplesRead) {
  for (const char* name : {"contact_rigid_punch.toml", "contact_rigid_sphere.toml", "contact_coated_indentation.toml",
                           "contact_roller_plates.toml"})
    EXPECT_NO_THROW(io::parse_contact_problem(example(name), name)) << name;
}

TEST(ContactErrors, RigidBodyWithoutLoadOrDisplacement) {
  const auto text = replaced(example("contact_rigid_punch.toml"), "[load]\nbody = \"punch\"\ncomponent = 2\nforce = \"-P\"", "");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "rigid body 'punch' has no load and no displacement")) << message;
  EXPECT_TRUE(contains(message, "key 'body[2]'")) << message;  // the rigid body's own table
}

TEST(ContactErrors, RigidBodyAsSideOne) {
  auto text = replaced(example("contact_rigid_punch.toml"), "body1 = \"block\"\nboundary1 = \"contact\"\nbody2 = \"punch\"",
                       "body1 = \"punch\"\nbody2 = \"block\"\nboundary2 = \"contact\"");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "contact[1].body1")) << message;
  EXPECT_TRUE(contains(message, "must be the second side")) << message;
}

TEST(ContactErrors, RigidProfileKeyOfAnotherProfile) {
  const auto message =
      input_error(replaced(example("contact_rigid_punch.toml"), "half_width = \"a\"", "half_width = \"a\"\nradius = 1.0"));
  EXPECT_TRUE(contains(message, "body[2].rigid.radius")) << message;
  EXPECT_TRUE(contains(message, "no effect")) << message;
}

TEST(ContactErrors, BoundaryInTwoContacts) {
  const auto text = example("contact_roller_plates.toml") +
                    "\n[[contact]]\nname = \"again\"\nbody1 = \"roller\"\nboundary1 = \"top contact\"\nbody2 = "
                    "\"bottom_plate\"\nboundary2 = \"top\"\n";
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "a boundary is in two contacts")) << message;
}

// Self-contact joins two boundaries of one body; one boundary against itself is refused.
TEST(ContactErrors, BoundaryInContactWithItself) {
  const auto text = example("contact_self_slot.toml");
  EXPECT_NO_THROW(io::parse_contact_problem(text, "slot.toml"));
  const auto message = input_error(replaced(text, "boundary2 = \"upper contact\"", "boundary2 = \"lower contact\""));
  EXPECT_TRUE(contains(message, "key 'contact[1].boundary2'")) << message;
  EXPECT_TRUE(contains(message, "cannot be in contact with itself")) << message;
}

// A self-contact holds none of its body's rigid motions: without the clamp the slot's body
// is free, and the first free motion named is a translation (the contact's pairs would
// otherwise be taken as holding it and leave a singular system).
TEST(ContactErrors, SelfContactHoldsNoRigidMotion) {
  const auto text = replaced(example("contact_self_slot.toml"), "elements = 8\nu1 = 0.0\nu2 = 0.0", "elements = 8");
  const auto problem = io::parse_contact_problem(text, "slot.toml").problem;
  const std::string message = solver_error(problem);
  EXPECT_TRUE(contains(message, "body 'block' is free to move: translation")) << message;
}

// Friction and kind may differ per contact; the tangential coupling (a property of the
// condensed operator) may not.
TEST(ContactErrors, DifferentCouplingsPerContact) {
  const auto text = replaced(example("contact_roller_plates.toml"), "[[contact]]\nname = \"top\"",
                             "[[contact]]\nname = \"top\"\nfriction = 0.2\ncoupling = false");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "contact[2].coupling")) << message;
  EXPECT_TRUE(contains(message, "same tangential coupling")) << message;
}

TEST(ContactErrors, BondInAOneRegionBody) {
  const auto text = replaced(example("contact_rigid_punch.toml"), "name = \"left\"", "name = \"left\"\ninterface = \"x\"");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "bonds regions of one body")) << message;
}

TEST(ContactErrors, ZeroPrescribedGapHasNoEffect) {
  const auto text = replaced(example("contact_rigid_punch.toml"), "normal = \"body1\"", "normal = \"body1\"\ngap = 0.0");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "contact[1].gap")) << message;
}

TEST(ContactErrors, OverlappingRigidBody) {
  // The punch face drawn 0.01 below the block's top: an overlap without interference.
  const auto text = replaced(example("contact_rigid_punch.toml"), "center = [0.0, 0.0]", "center = [0.0, -0.01]");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "the bodies overlap")) << message;
  EXPECT_TRUE(contains(message, "rigid body 'punch'")) << message;
}

}  // namespace bemcontact

namespace bemcontact {

TEST(ContactErrors, AnEndTimeBeforeTheAmplitudesEndIsAWarningNamingIt) {
  // The tube unloads from t = 1 to 2: end_time = 1 leaves the unloading out, said at the key.
  const auto text = test_support::example_text("plastic_tube_bonded.toml");
  const auto cut =
      io::parse_contact_problem(test_support::replaced(text, "end_time = 2.0", "end_time = 1.0"), "tube.toml");
  ASSERT_EQ(cut.warnings.size(), 1u);
  EXPECT_NE(cut.warnings[0].find("tube.toml:"), std::string::npos) << cut.warnings[0];
  EXPECT_NE(cut.warnings[0].find("history.end_time"), std::string::npos) << cut.warnings[0];
  EXPECT_NE(cut.warnings[0].find("until t = 2"), std::string::npos) << cut.warnings[0];
  EXPECT_TRUE(io::parse_contact_problem(text, "tube.toml").warnings.empty());
}

TEST(ContactErrors, ALargeInterferenceIsAWarning) {
  auto file = io::parse_contact_problem(test_support::example_text("contact_shrink_fit.toml"), "fit.toml", {{"delta", 0.5}});
  const auto prepared = contact::prepare_contact(file.problem);
  ASSERT_EQ(prepared.warnings.size(), 1u);
  EXPECT_NE(prepared.warnings[0].find("small strains"), std::string::npos) << prepared.warnings[0];
  file = io::parse_contact_problem(test_support::example_text("contact_shrink_fit.toml"), "fit.toml");
  EXPECT_TRUE(contact::prepare_contact(file.problem).warnings.empty());
}

}  // namespace bemcontact

namespace bemcontact {

// The README's ball at a load whose Hertz radius (0.163) outgrows both zones (r <= 0.1):
// refused at the step where it happens, naming both zones and where to lengthen them.
TEST(ContactErrors, ContactOutgrowingItsZonesIsRefused) {
  const auto text = test_support::replaced(example_text(), "\nP = 31.5", "\nP = 400.0");
  const auto message = solver_error(io::parse_contact_problem(text, "ball.toml").problem);
  EXPECT_TRUE(contains(message, "contact 'contact' is clipped by its zones at load step 1 (t = 1)")) << message;
  EXPECT_TRUE(contains(message, "boundary 'contact' of body 'ball' (side 1, running on into 'arc')")) << message;
  EXPECT_TRUE(contains(message, "boundary 'contact' of body 'support' (side 2, running on into 'top')")) << message;
  EXPECT_TRUE(contains(message, "past r = 0.19867")) << message;
}

// Only the support's zone too short (r <= 0.1 under a contact of radius 0.118): side 2.
TEST(ContactErrors, ContactOutgrowingTheSecondZoneIsRefused) {
  auto text = test_support::replaced(example_text(), "\nP = 31.5", "\nP = 150.0");
  text = test_support::replaced(text, "rc = 0.1", "rc = 0.2");
  text = test_support::replaced(text, "b = \"rc\"", "b = 0.1");
  const auto message = solver_error(io::parse_contact_problem(text, "ball.toml").problem);
  EXPECT_TRUE(contains(message, "is clipped by its zone at load step 1")) << message;
  EXPECT_TRUE(contains(message, "boundary 'contact' of body 'support' (side 2")) << message;
  EXPECT_FALSE(contains(message, "body 'ball'")) << message;
}

// A zone reaching past the contact is solved as before (the example: a = 0.070 in r <= 0.1).
TEST(ContactErrors, ZonesLongerThanTheContactAreNotClipped) {
  EXPECT_NO_THROW(contact::solve_contact(io::parse_contact_problem(example_text(), "ball.toml").problem));
}

}  // namespace bemcontact

namespace bemcontact {

// A contact's law written where it has no effect: said where it belongs.
TEST(ContactErrors, FrictionInTheSolverTableBelongsToTheContact) {
  auto text = test_support::example_text("fretting_cylinder.toml");
  text = test_support::replaced(text, "[solver]\n", "[solver]\nfriction = 0.2\n");
  const auto message = input_error(text);
  EXPECT_TRUE(contains(message, "key 'solver.friction'")) << message;
  EXPECT_TRUE(contains(message, "'friction' belongs in each [[contact]] table")) << message;
}

// A normal force of the wrong sign: the failure says it pulls the bodies apart.
TEST(ContactErrors, ALoadPullingTheContactOpenIsNamed) {
  const auto text = test_support::replaced(example_text(), "force = \"-P\"", "force = \"P\"");
  const auto message = solver_error(io::parse_contact_problem(text, "ball.toml").problem);
  EXPECT_TRUE(contains(message, "Load 'ball_top_y' (force 31.5 along z) pulls body 'ball' away from contact 'contact'"))
      << message;
  EXPECT_TRUE(contains(message, "reverse its sign")) << message;
}

// Names become parts of output file names: long ones, control characters and names whose
// files would coincide are refused where they are written.
TEST(ContactErrors, NamesThatCannotBeFileNames) {
  const std::string long_name(3000, 'b');
  const auto long_body = input_error(replaced(replaced(example_text(), "name = \"ball\"", "name = \"" + long_name + "\""),
                                              "body = \"ball\"", "body = \"" + long_name + "\""));
  EXPECT_TRUE(contains(long_body, "ball.toml:31: key 'body[1].name'")) << long_body;
  EXPECT_TRUE(contains(long_body, "3000 characters long, over the limit of 100")) << long_body;
  EXPECT_LT(long_body.size(), 300u);  // the name is cut in the message
  const auto long_boundary = input_error(replaced(example_text(), "name = \"arc\"", "name = \"" + std::string(101, 'a') + "\""));
  EXPECT_TRUE(contains(long_boundary, "key 'body[1].boundary[2].name'")) << long_boundary;
  EXPECT_TRUE(contains(long_boundary, "101 characters long")) << long_boundary;
  const auto tab = input_error(replaced(example_text(), "name = \"arc\"", "name = \"a\\tc\""));
  EXPECT_TRUE(contains(tab, "a control character (code 9)")) << tab;
  // 100 characters of two bytes each are 100 characters.
  std::string accented;
  for (int k = 0; k < 100; ++k) accented += "\xc3\xa9";
  EXPECT_EQ(input_error(replaced(example_text(), "name = \"arc\"", "name = \"" + accented + "\"")), "no error");
}

TEST(ContactErrors, NamesWhoseFilesWouldCoincide) {
  // "ball" and "support" renamed "sup port" and "sup_port": one sup_port_boundary.csv.
  std::string text = replaced(replaced(example_text(), "name = \"ball\"", "name = \"sup port\""), "body = \"ball\"",
                              "body = \"sup port\"");
  text = replaced(text, "name = \"support\"", "name = \"sup_port\"");
  const auto bodies = input_error(text);
  EXPECT_TRUE(contains(bodies, "key 'body[2].name'")) << bodies;
  EXPECT_TRUE(contains(bodies, "the output file 'sup_port_boundary.csv' of body 'sup_port' would also be that of body "
                               "'sup port' (line 31)")) << bodies;
  // A contact named after a body's file, or after the run's own motions.csv.
  const auto named = [&](const std::string& name) {
    std::string multi = replaced(example_text(), "[contact]\n", "[[contact]]\nname = \"" + name +
                                                                  "\"\nbody1 = \"ball\"\nbody2 = \"support\"\n");
    multi = replaced(multi, "increments = 1\n", "");
    return input_error(replaced(multi, "[contact.load]", "[solver]\nincrements = 1\n[load]"));
  };
  EXPECT_EQ(named("ball contact"), "no error");
  const auto contact = named("ball boundary");
  EXPECT_TRUE(contains(contact, "of contact 'ball boundary' would also be that of body 'ball'")) << contact;
  const auto motions = named("motions");
  EXPECT_TRUE(contains(motions, "would also be that of the run's own motions.csv")) << motions;
}

}  // namespace bemcontact

namespace bemcontact {
namespace {

std::string rough_text() { return test_support::example_text("contact_rough_profile.toml"); }

std::string rough_error(const std::string& text) {
  try {
    io::parse_contact_problem(text, "rough.toml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace

// Keys of another profile and values that describe no rough profile, named by their key.
TEST(ContactErrors, RoughProfileKeys) {
  EXPECT_NO_THROW(io::parse_contact_problem(rough_text(), "rough.toml"));
  auto message = rough_error(replaced(rough_text(), "seed = 7", "seed = 7\nradius = 1.0"));
  EXPECT_TRUE(contains(message, "rough.toml:") && contains(message, "body[2].rigid.radius")) << message;
  EXPECT_TRUE(contains(message, "no effect")) << message;
  message = rough_error(replaced(rough_text(), "seed = 7", "seed = 7\npoints_file = \"p.csv\""));
  EXPECT_TRUE(contains(message, "body[2].rigid.points_file") && contains(message, "contour profile only")) << message;
  message = rough_error(replaced(rough_text(), "hurst = 0.8", "hurst = 1.0"));
  EXPECT_TRUE(contains(message, "body[2].rigid.hurst") && contains(message, "0 < hurst < 1")) << message;
  message = rough_error(replaced(rough_text(), "short_wavelength = 0.1", "short_wavelength = 0.004"));
  EXPECT_TRUE(contains(message, "body[2].rigid.short_wavelength") && contains(message, "Nyquist")) << message;
  message = rough_error(replaced(rough_text(), "long_wavelength = 2.0", "long_wavelength = 5.0"));
  EXPECT_TRUE(contains(message, "body[2].rigid.long_wavelength") && contains(message, "exceeds")) << message;
  message = rough_error(replaced(rough_text(), "rms_height = \"rms\"", "rms_height = 0.0"));
  EXPECT_TRUE(contains(message, "body[2].rigid.rms_height")) << message;
  message = rough_error(replaced(rough_text(), "samples = 1601", ""));
  EXPECT_TRUE(contains(message, "body[2].rigid") && contains(message, "samples")) << message;
  // Keys of the rough profile on another one.
  message = rough_error(replaced(example("contact_rigid_punch.toml"), "half_width = \"a\"", "half_width = \"a\"\nhurst = 0.5"));
  EXPECT_TRUE(contains(message, "body[2].rigid.hurst") && contains(message, "rough profile only")) << message;
}

// A contour from a CSV file: relative to the problem file; its errors name the CSV file and
// line; points and points_file together are refused.
TEST(ContactErrors, ContourPointsFile) {
  const auto dir = std::filesystem::temp_directory_path() / ("bemcontact_contour_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string face = "profile = \"flat\"\ncenter = [0.0, 0.0]    # middle of the face, touching the block\nhalf_width = \"a\"";
  auto text = replaced(example("contact_rigid_punch.toml"), face, "profile = \"contour\"\npoints_file = \"face.csv\"");
  std::ofstream(dir / "punch.toml") << text;
  std::ofstream(dir / "face.csv") << "x,y\n-1.0,0.0\n1.0,0.0\n";
  const auto file = io::read_contact_file(dir / "punch.toml");
  EXPECT_EQ(file.problem.bodies[1].rigid->contour.size(), 1u);
  std::ofstream(dir / "face.csv") << "x,y\n-1.0,0.0\n1.0,0.0\n0.5,0.0\n";
  std::string message;
  try {
    io::read_contact_file(dir / "punch.toml");
  } catch (const InputError& error) {
    message = error.what();
    EXPECT_EQ(error.where().file, (dir / "face.csv").string());
    EXPECT_EQ(error.where().line, 4);
    EXPECT_EQ(error.where().key, "body[2].rigid.points_file");
  }
  EXPECT_TRUE(contains(message, "increase strictly")) << message;
  std::ofstream(dir / "punch.toml") << replaced(text, "points_file", "points = [[-1.0, 0.0], [1.0, 0.0]]\npoints_file");
  message.clear();
  try {
    io::read_contact_file(dir / "punch.toml");
  } catch (const InputError& error) {
    message = error.what();
  }
  EXPECT_TRUE(contains(message, "not both")) << message;
  std::filesystem::remove_all(dir);
}

}  // namespace bemcontact
