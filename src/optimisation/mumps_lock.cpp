// mumps_lock.cpp: dmumps_c, MUMPS's C entry, forwarded to MUMPS's own under one process-wide mutex
// (see mumps_lock.hpp). Only solves whose KKT systems are too large for the dense solver
// (dense_kkt_solver.hpp, kDenseKktMaxDimension) call MUMPS, and the dense solves that end a MUMPS
// instance left by their session's previous solve (IPOPT keeps its algorithm until the next one).
#include "optimisation/mumps_lock.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace rodshape::detail {

namespace {

thread_local long calls_in_this_thread = 0;

using MumpsEntry = void (*)(void*);

/// MUMPS's dmumps_c: the next definition after ours in the search order.
MumpsEntry next_dmumps_c() {
  static const MumpsEntry entry = [] {
    void* symbol = dlsym(RTLD_NEXT, "dmumps_c");
    if (symbol == nullptr) {
      std::fputs("rodshape: MUMPS's dmumps_c not found behind the lock\n", stderr);
      std::abort();
    }
    return reinterpret_cast<MumpsEntry>(symbol);
  }();
  return entry;
}

}  // namespace

long mumps_calls_in_this_thread() { return calls_in_this_thread; }

}  // namespace rodshape::detail

/// IPOPT's calls of MUMPS (job -1 initialise, 1 analyse, 2 factorise, 3 solve, -2 end), one at a
/// time. The structure is MUMPS's DMUMPS_STRUC_C, passed through untouched.
extern "C" __attribute__((visibility("default"))) void dmumps_c(void* id) {
  static std::mutex mumps;
  const rodshape::detail::MumpsEntry entry = rodshape::detail::next_dmumps_c();
  const std::lock_guard<std::mutex> lock(mumps);
  ++rodshape::detail::calls_in_this_thread;
  entry(id);
}
