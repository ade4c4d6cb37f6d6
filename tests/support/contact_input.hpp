#pragma once
// Contact problem texts that should be refused: the reader's message, for the tests that
// check what it names.
#include <string>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"

namespace bemcontact::test_support {

// The InputError's message for the text read as `file_name`, or "no error".
inline std::string contact_input_error(const std::string& text, const std::string& file_name) {
  try {
    io::parse_contact_problem(text, file_name);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

inline bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace bemcontact::test_support
