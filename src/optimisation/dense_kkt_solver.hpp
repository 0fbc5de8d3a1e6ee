// dense_kkt_solver.hpp (private): a dense symmetric-indefinite solver for IPOPT's small KKT
// systems, behind the Fortran interface of HSL's MA27 so that IPOPT 3.11's "linear_solver ma27"
// uses it. Debian's libipopt has no HSL but exports its linear-solver loader; LSL_setMA27 hands it
// the four entries below, and IPOPT's own Ma27TSolverInterface then calls them (analyse once per
// solve, factorise and solve every iteration).
//
// The matrix is assembled densely from IPOPT's triplets, equilibrated symmetrically (S A S, a few
// Ruiz passes: a congruence, so the inertia is unchanged) and factorised by LAPACK's Bunch–Kaufman
// dsytrf (P S A S Pᵀ = L D Lᵀ, D of 1×1 and 2×2 blocks), which gives the inertia IPOPT checks;
// dsytrs solves. Everything lives in the arrays IPOPT passes (its A, IW): no state of our own, so
// factorisations in different threads run at once, with no lock (MUMPS needs one, mumps_lock.hpp).
//
// Storage, asked for by analyse() through INFO(5), INFO(6) (NRLNEC, NIRNEC):
//   A:  [0, nz) IPOPT's values (left as they are), then the dense factor (n², column-major, lower
//       triangle), S (n), dsytrf's workspace (n: its unblocked factorisation, best at these
//       sizes);
//   IW: [0] the factor's offset in A (nz: the solve is not told nz), [1, n] dsytrf's pivots.
// A factorisation with less space says so the way MA27 does (IFLAG -3 for IW, -4 for A, the size
// needed in IERROR), and IPOPT grows its arrays and calls again.
//
// Zero pivots: a 1×1 pivot, or an eigenvalue of a 2×2 block, of size ≤ n ε max|(S A S)_ij| counts
// as zero (the matrix is singular to working precision); then IFLAG = 3 and IERROR = the rank, as
// MA27 reports, and IPOPT regularises the matrix (its default ma27_ignore_singularity = no).
#pragma once

namespace rodshape::detail {

/// IPOPT's Fortran integer (ipfint).
using FortranInt = int;

/// Largest KKT dimension (IPOPT's n_x + n_s + n_c + n_d, plus 2 × the L-BFGS history with the
/// limited-memory Hessian) for which IpoptSession uses the dense solver; MUMPS above (see
/// BENCHMARKS.md for the measurement).
inline constexpr int kDenseKktMaxDimension = 160;

/// Makes the dense solver IPOPT's MA27 (LSL_setMA27), once per process; call before a solve with
/// linear_solver ma27. Thread-safe.
void register_dense_kkt_solver();

/// MA27's entries, with MA27's arguments (1-based indices; see IpMa27TSolverInterface.cpp in
/// IPOPT 3.11). Public for the tests.
namespace dense_kkt {

/// MA27ID: default controls (unused by the dense solver, set for IPOPT's sake).
void defaults(FortranInt* icntl, double* cntl);
/// MA27AD: checks the structure and reports the storage needed in info[4] (A) and info[5] (IW);
/// info[0] = 0, or 1 with info[1] entries out of range (IPOPT stops), -1 for n < 1, -2 for nz < 0.
void analyse(FortranInt* n,
             FortranInt* nz,
             const FortranInt* irn,
             const FortranInt* icn,
             FortranInt* iw,
             FortranInt* liw,
             FortranInt* ikeep,
             FortranInt* iw1,
             FortranInt* nsteps,
             FortranInt* iflag,
             FortranInt* icntl,
             double* cntl,
             FortranInt* info,
             double* ops);
/// MA27BD: factorises the matrix whose nz values are a[0, nz) (duplicates summed, either
/// triangle). info[0]: 0; 3 when singular (info[1] the rank); -3 / -4 when liw / la is too small
/// (info[1] the size needed). info[14]: the number of negative eigenvalues.
void factorise(FortranInt* n,
               FortranInt* nz,
               const FortranInt* irn,
               const FortranInt* icn,
               double* a,
               FortranInt* la,
               FortranInt* iw,
               FortranInt* liw,
               FortranInt* ikeep,
               FortranInt* nsteps,
               FortranInt* maxfrt,
               FortranInt* iw1,
               FortranInt* icntl,
               double* cntl,
               FortranInt* info);
/// MA27CD: overwrites rhs with the solution, from factorise()'s factor.
void solve(FortranInt* n,
           double* a,
           FortranInt* la,
           FortranInt* iw,
           FortranInt* liw,
           double* w,
           FortranInt* maxfrt,
           double* rhs,
           FortranInt* iw1,
           FortranInt* nsteps,
           FortranInt* icntl,
           double* cntl);

}  // namespace dense_kkt

}  // namespace rodshape::detail
