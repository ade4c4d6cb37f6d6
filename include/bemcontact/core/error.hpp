#pragma once
// Error reporting: one choke point for every failure a user can see.
//  - InputError: the problem file is wrong; names file, line and key.
//  - GeometryError: the boundary is not a valid domain; names the boundary or vertex.
//  - SolverError: a numerical failure (singular system, no convergence); says what and where.
// Internal invariants use BEMCONTACT_ASSERT, active in debug builds only.
#include <stdexcept>
#include <string>

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
 private:
  SourceLocation where_;
};

class GeometryError : public Error {
 public:
  using Error::Error;
};

class SolverError : public Error {
 public:
  using Error::Error;
};

}  // namespace bemcontact

#ifdef NDEBUG
#define BEMCONTACT_ASSERT(condition) ((void)0)
#else
#include <cassert>
#define BEMCONTACT_ASSERT(condition) assert(condition)
#endif
