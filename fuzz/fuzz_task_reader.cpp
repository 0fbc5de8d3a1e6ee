// fuzz_task_reader.cpp: libFuzzer target for the task reader. Arbitrary bytes go through
// parse_equilibrium_task and parse_plan_task; an InputError is the expected answer to bad input.
// Anything else thrown, a crash, a sanitizer report or a timeout is a finding.
//   scripts/fuzz.sh runs it (seed corpus: examples/*.yaml).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/io/task_reader.hpp"

namespace {

template <class Parse>
void expect_input_error_or_nothing(const char* what, Parse&& parse) {
  try {
    parse();
  } catch (const rodshape::InputError&) {
    // bad input, said as such
  } catch (const std::exception& error) {
    std::fprintf(stderr, "finding: %s threw something else than InputError: %s\n", what,
                 error.what());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Relative paths in the task (robot.urdf) resolve from the working directory: scripts/fuzz.sh
  // runs the fuzzer in examples/, where the seeds' paths lead to data/robots/.
  expect_input_error_or_nothing("parse_equilibrium_task",
                                [&] { rodshape::parse_equilibrium_task(text, "fuzz.yaml"); });
  expect_input_error_or_nothing("parse_plan_task",
                                [&] { rodshape::parse_plan_task(text, "fuzz.yaml"); });
  return 0;
}
