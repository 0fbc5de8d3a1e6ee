// version.cpp: rodshape::version(), from the RODSHAPE_VERSION the build defines for this file.
#include "rodshape/version.hpp"

#ifndef RODSHAPE_VERSION
#error "RODSHAPE_VERSION is defined by CMakeLists.txt from project(VERSION)"
#endif

namespace rodshape {

std::string version() { return RODSHAPE_VERSION; }

}  // namespace rodshape
