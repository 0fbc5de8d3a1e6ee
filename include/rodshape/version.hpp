// version.hpp: the library's version, as the build was configured (CMake's project() VERSION).
#pragma once

#include <string>

namespace rodshape {

/// "MAJOR.MINOR.PATCH", e.g. "0.1.0".
std::string version();

}  // namespace rodshape
