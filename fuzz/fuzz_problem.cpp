// libFuzzer target: problem text -> parse -> mesh -> solve -> output files, judged by
// the oracle (problem_oracle.hpp). `make fuzz` builds it with clang and AddressSanitizer +
// UndefinedBehaviorSanitizer and runs it from the examples with the key dictionary.
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "problem_oracle.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  omp_set_num_threads(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string failure = bemcontact::fuzz::check_problem_text(text);
  if (!failure.empty()) {
    std::fprintf(stderr, "ORACLE FAILURE: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
