// dense_kkt_solver.cpp: IPOPT's MA27 entries as a dense Bunch–Kaufman LDLᵀ (see
// dense_kkt_solver.hpp).
#include "optimisation/dense_kkt_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <mutex>

// LAPACK (reference LAPACK through IPOPT's link line), with gfortran's hidden string lengths.
extern "C" {
void dsytrf_(const char* uplo,
             const int* n,
             double* a,
             const int* lda,
             int* ipiv,
             double* work,
             const int* lwork,
             int* info,
             std::size_t uplo_length);
void dsytrs_(const char* uplo,
             const int* n,
             const int* nrhs,
             const double* a,
             const int* lda,
             const int* ipiv,
             double* b,
             const int* ldb,
             int* info,
             std::size_t uplo_length);

// IPOPT's linear-solver loader (HSLLoader.h, not shipped by Debian): MA27's entries for
// Ma27TSolverInterface, whose signatures are those of dense_kkt's four functions.
using Ma27ad = decltype(&rodshape::detail::dense_kkt::analyse);
using Ma27bd = decltype(&rodshape::detail::dense_kkt::factorise);
using Ma27cd = decltype(&rodshape::detail::dense_kkt::solve);
using Ma27id = decltype(&rodshape::detail::dense_kkt::defaults);
void LSL_setMA27(Ma27ad ma27ad, Ma27bd ma27bd, Ma27cd ma27cd, Ma27id ma27id);
}

namespace rodshape::detail {

namespace {

constexpr int kInfoSize = 20;  // MA27's INFO(20)
constexpr int kScalingPasses = 3;

// Sizes of the storage described in the header (64-bit: n² overflows int for n > 46340).
long long real_storage(long long n, long long nz) { return nz + n * n + 2 * n; }
long long integer_storage(long long n) { return 1 + n; }

FortranInt clamp_to_int(long long value) {
  return static_cast<FortranInt>(
      std::min<long long>(value, std::numeric_limits<FortranInt>::max()));
}

}  // namespace

namespace dense_kkt {

void defaults(FortranInt* icntl, double* cntl) {
  std::fill(icntl, icntl + 30, 0);
  std::fill(cntl, cntl + 5, 0.0);
  cntl[0] = 0.1;  // MA27's pivot threshold u (IPOPT overwrites it; Bunch–Kaufman has its own)
  cntl[1] = 1.0;
}

void analyse(FortranInt* n,
             FortranInt* nz,
             const FortranInt* irn,
             const FortranInt* icn,
             FortranInt* /*iw*/,
             FortranInt* /*liw*/,
             FortranInt* /*ikeep*/,
             FortranInt* /*iw1*/,
             FortranInt* nsteps,
             FortranInt* /*iflag*/,
             FortranInt* /*icntl*/,
             double* /*cntl*/,
             FortranInt* info,
             double* ops) {
  std::fill(info, info + kInfoSize, 0);
  *nsteps = 1;  // IPOPT sizes the solve's scratch IW1 by it
  *ops = 0.0;
  if (*n < 1) {
    info[0] = -1;
    return;
  }
  if (*nz < 0) {
    info[0] = -2;
    return;
  }
  FortranInt out_of_range = 0;
  for (FortranInt k = 0; k < *nz; ++k)
    if (irn[k] < 1 || irn[k] > *n || icn[k] < 1 || icn[k] > *n) ++out_of_range;
  if (out_of_range > 0) {
    info[0] = 1;
    info[1] = out_of_range;
  }
  info[4] = clamp_to_int(real_storage(*n, *nz));
  info[5] = clamp_to_int(integer_storage(*n));
  *ops = static_cast<double>(*n) * *n * *n / 3.0;
}

void factorise(FortranInt* n,
               FortranInt* nz,
               const FortranInt* irn,
               const FortranInt* icn,
               double* a,
               FortranInt* la,
               FortranInt* iw,
               FortranInt* liw,
               FortranInt* /*ikeep*/,
               FortranInt* /*nsteps*/,
               FortranInt* maxfrt,
               FortranInt* /*iw1*/,
               FortranInt* /*icntl*/,
               double* /*cntl*/,
               FortranInt* info) {
  std::fill(info, info + kInfoSize, 0);
  *maxfrt = 1;  // IPOPT sizes the solve's scratch W by it
  const FortranInt size = *n, entries = *nz;
  if (size < 1 || entries < 0) {
    info[0] = size < 1 ? -1 : -2;
    return;
  }
  if (*liw < integer_storage(size)) {
    info[0] = -3;
    info[1] = clamp_to_int(integer_storage(size));
    return;
  }
  if (*la < real_storage(size, entries)) {
    info[0] = -4;
    info[1] = clamp_to_int(real_storage(size, entries));
    return;
  }
  const std::size_t dim = static_cast<std::size_t>(size);
  double* const dense = a + entries;
  double* const scale = dense + dim * dim;
  double* const work = scale + dim;
  int* const pivots = iw + 1;
  iw[0] = entries;

  // Assemble the lower triangle: (i, j) and (j, i) are the same entry; duplicates are summed.
  std::fill(dense, dense + dim * dim, 0.0);
  for (FortranInt k = 0; k < entries; ++k) {
    const FortranInt i = irn[k] - 1, j = icn[k] - 1;
    if (i < 0 || i >= size || j < 0 || j >= size) continue;  // MA27 ignores these too
    dense[static_cast<std::size_t>(std::max(i, j)) +
          dim * static_cast<std::size_t>(std::min(i, j))] += a[k];
  }
  // Symmetric equilibration S A S (Ruiz: each row's largest entry towards 1; a congruence, so the
  // inertia is A's): IPOPT's KKT systems mix barrier terms of 1e10 with entries of 1e-10, and
  // MUMPS, the other solver, scales them too (IPOPT's mumps_scaling).
  std::fill(scale, scale + dim, 1.0);
  for (int pass = 0; pass < kScalingPasses; ++pass) {
    std::fill(work, work + dim, 0.0);  // the rows' largest |entries|
    for (std::size_t j = 0; j < dim; ++j)
      for (std::size_t i = j; i < dim; ++i) {
        const double entry = std::abs(dense[i + dim * j]);
        work[i] = std::max(work[i], entry);
        work[j] = std::max(work[j], entry);
      }
    for (std::size_t i = 0; i < dim; ++i) work[i] = work[i] > 0.0 ? 1.0 / std::sqrt(work[i]) : 1.0;
    for (std::size_t j = 0; j < dim; ++j)
      for (std::size_t i = j; i < dim; ++i) dense[i + dim * j] *= work[i] * work[j];
    for (std::size_t i = 0; i < dim; ++i) scale[i] *= work[i];
  }
  double largest = 0.0;
  for (std::size_t j = 0; j < dim; ++j)
    for (std::size_t i = j; i < dim; ++i) largest = std::max(largest, std::abs(dense[i + dim * j]));

  int lapack_info = 0;
  const int lwork = size;
  dsytrf_("L", &size, dense, &size, pivots, work, &lwork, &lapack_info, 1);
  if (lapack_info < 0) {  // an argument refused: cannot happen with the sizes above
    info[0] = -1;
    return;
  }

  // Inertia from D: a 1×1 block is its own eigenvalue; a 2×2 block [p q; q r] has eigenvalues
  // m ± √(((p - r)/2)² + q²), m = (p + r)/2, the smaller one computed as det / the larger.
  const double zero = static_cast<double>(size) * std::numeric_limits<double>::epsilon() * largest;
  FortranInt negative = 0, zeros = 0;
  const auto count = [&](double eigenvalue) {
    if (std::abs(eigenvalue) <= zero)
      ++zeros;
    else if (eigenvalue < 0.0)
      ++negative;
  };
  for (std::size_t k = 0; k < dim;) {
    const double p = dense[k + dim * k];
    if (pivots[k] > 0) {
      count(p);
      k += 1;
    } else {
      const double q = dense[k + 1 + dim * k], r = dense[k + 1 + dim * (k + 1)];
      const double mean = 0.5 * (p + r), radius = std::hypot(0.5 * (p - r), q);
      const double larger = mean + std::copysign(radius, mean);
      count(larger);
      count(larger == 0.0 ? 0.0 : (p * r - q * q) / larger);
      k += 2;
    }
  }
  if (zeros > 0) {
    info[0] = 3;
    info[1] = size - zeros;  // the rank
  }
  info[8] = clamp_to_int(static_cast<long long>(size) * size);  // reals and integers in the factor
  info[9] = clamp_to_int(integer_storage(size));
  info[14] = negative;
}

void solve(FortranInt* n,
           double* a,
           FortranInt* /*la*/,
           FortranInt* iw,
           FortranInt* /*liw*/,
           double* /*w*/,
           FortranInt* /*maxfrt*/,
           double* rhs,
           FortranInt* /*iw1*/,
           FortranInt* /*nsteps*/,
           FortranInt* /*icntl*/,
           double* /*cntl*/) {
  // A x = b as (S A S) (S⁻¹ x) = S b.
  const std::size_t dim = static_cast<std::size_t>(*n);
  const double* const scale = a + iw[0] + dim * dim;
  for (std::size_t i = 0; i < dim; ++i) rhs[i] *= scale[i];
  const int one = 1;
  int lapack_info = 0;
  dsytrs_("L", n, &one, a + iw[0], n, iw + 1, rhs, n, &lapack_info, 1);
  for (std::size_t i = 0; i < dim; ++i) rhs[i] *= scale[i];
}

}  // namespace dense_kkt

void register_dense_kkt_solver() {
  static std::once_flag once;
  std::call_once(once, [] {
    LSL_setMA27(dense_kkt::analyse, dense_kkt::factorise, dense_kkt::solve, dense_kkt::defaults);
  });
}

}  // namespace rodshape::detail
