// mumps_lock.hpp (private): the one lock around MUMPS. Debian's IPOPT 3.11 factorises the KKT
// systems too large for rodshape's dense solver (dense_kkt_solver.hpp, which needs no lock) with
// the sequential MUMPS 5.5, whose Fortran modules keep their working state (communication buffers,
// load and out-of-core bookkeeping) in process-wide variables, so two factorisations at once
// corrupt each other (seen without a lock: segfaults in DMUMPS_LOAD_UPDATE, "PB allocation in
// DMUMPS_LOAD_INIT", "Attempt to DEALLOCATE unallocated 'load_flops'" at dmumps_load.F:1121).
// Everything IPOPT asks of MUMPS goes through one C entry, dmumps_c; mumps_lock.cpp defines
// dmumps_c in our image, which the dynamic linker binds IPOPT's calls to before MUMPS's own, and
// forwards each call to MUMPS's under a process-wide mutex. The rest of an IPOPT solve then runs in
// parallel.
#pragma once

namespace rodshape::detail {

/// Calls of dmumps_c that went through the lock from this thread so far. IpoptSession::run() uses
/// it to check, on its first MUMPS solve, that IPOPT's calls really are bound to the lock (they are
/// not when an image that defines dmumps_c was loaded before ours); until then it serialises whole
/// MUMPS solves (never the dense solver's).
long mumps_calls_in_this_thread();

}  // namespace rodshape::detail
