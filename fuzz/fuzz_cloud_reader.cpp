// fuzz_cloud_reader.cpp: libFuzzer target for the cloud readers (io/cloud_reader.hpp). Arbitrary
// bytes go through the PLY, PCD and CSV parsers, each; an InputError is the expected answer to bad
// input. Anything else thrown, a crash, a sanitizer report or a timeout is a finding, and so is a
// cloud beyond the point cap or with a non-finite point.
//   scripts/fuzz.sh runs it (seed corpus: fuzz/seeds/cloud/).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

#include "rodshape/error.hpp"
#include "rodshape/feedback/cloud_estimator.hpp"
#include "rodshape/io/cloud_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (const rodshape::CloudFormat format :
       {rodshape::CloudFormat::Ply, rodshape::CloudFormat::Pcd, rodshape::CloudFormat::Csv}) {
    try {
      const auto points = rodshape::parse_cloud(bytes, format, "fuzz");
      if (points.size() > static_cast<std::size_t>(rodshape::kMaxCloudPoints)) {
        std::fprintf(stderr, "finding: %zu points, beyond the cap\n", points.size());
        std::abort();
      }
      for (const auto& p : points)
        if (!p.allFinite()) {
          std::fprintf(stderr, "finding: a non-finite point was returned\n");
          std::abort();
        }
    } catch (const rodshape::InputError&) {
      // bad input, said as such
    } catch (const std::exception& error) {
      std::fprintf(stderr, "finding: parse_cloud threw something else than InputError: %s\n",
                   error.what());
      std::abort();
    }
  }
  return 0;
}
