#pragma once
// Error reporting: one choke point for every failure a user can see.
//  - InputError: the problem file is wrong; names file, line and key.
//  - GeometryError: the boundary is not a valid domain; names the boundary or vertex.
//  - SolverError: a numerical failure (singular system, no convergence); says what and where.
// Internal invariants use BEMCONTACT_ASSERT, active in debug builds only.
#include <stdexcept>
#include <string>
#include <vector>

namespace bemcontact {

// Where in a problem file a value came from. line = 0 when unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  std::string key;
  std::string describe() const;  // "file:line: key 'k'"
};

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InputError : public Error {
 public:
  InputError(const SourceLocation& where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  const std::string& detail() const { return detail_; }  // the message without the place
 private:
  SourceLocation where_;
  std::string detail_;
};

// Names the boundaries it is about and, when they come from a file, their places: the
// first place starts the message as in InputError ("file:line: key 'k': ..."); the others
// are in the message, next to their names.
class GeometryError : public Error {
 public:
  explicit GeometryError(const std::string& message);
  GeometryError(std::vector<SourceLocation> where, const std::string& message);
  const std::vector<SourceLocation>& where() const { return where_; }
  const std::string& detail() const { return detail_; }  // the message without the place
  // The same error with `context` ("body 'b'") before its message, the places kept.
  GeometryError in_context(const std::string& context) const;

 private:
  std::vector<SourceLocation> where_;  // only places with a file or a line
  std::string detail_;
};

// What a solver failure is about, where known (the Python module gives it as attributes):
// the part that failed, its iterations and relative residual, the load step and its
// pseudo-time.
struct SolverFailure {
  std::string part;         // "contact step", "contact zone", "interface GMRES", "factorisation", ...
  int iterations = -1;      // -1: not an iteration
  double residual = -1.0;   // relative; -1: none
  int step = -1;            // load step (1-based); -1: none
  double time = -1.0;       // its pseudo-time; -1: none
};

class SolverError : public Error {
 public:
  explicit SolverError(const std::string& message, SolverFailure failure = {})
      : Error(message), failure_(std::move(failure)) {}
  const SolverFailure& failure() const { return failure_; }

 private:
  SolverFailure failure_;
};

}  // namespace bemcontact

#ifdef NDEBUG
#define BEMCONTACT_ASSERT(condition) ((void)0)
#else
#include <cassert>
#define BEMCONTACT_ASSERT(condition) assert(condition)
#endif
