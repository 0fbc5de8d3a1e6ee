// test_dense_kkt_solver.cpp: the dense solver behind IPOPT's MA27 interface (dense_kkt_solver.hpp),
// called the way IPOPT 3.11's Ma27TSolverInterface calls it, against Eigen: solutions to LAPACK's
// backward error, the inertia, singular matrices flagged, duplicate entries summed, and the
// "insufficient space" answers IPOPT grows its arrays on.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>
#include <vector>

#include "optimisation/dense_kkt_solver.hpp"

namespace rodshape {
namespace test_dense_kkt_solver {
namespace {

using detail::FortranInt;
namespace kkt = detail::dense_kkt;

/// A symmetric matrix as IPOPT's triplets (1-based), values in a[0, nz).
struct Triplets {
  FortranInt n = 0;
  std::vector<FortranInt> irn, icn;
  std::vector<double> values;
  void add(int i, int j, double value) {
    irn.push_back(i + 1);
    icn.push_back(j + 1);
    values.push_back(value);
  }
};

/// The lower triangle of `m`, every entry given once.
Triplets lower_triangle(const Eigen::MatrixXd& m) {
  Triplets t;
  t.n = static_cast<FortranInt>(m.rows());
  for (int j = 0; j < m.cols(); ++j)
    for (int i = j; i < m.rows(); ++i)
      if (m(i, j) != 0.0) t.add(i, j, m(i, j));
  return t;
}

/// One analysis, factorisation and solve, IPOPT's way.
struct Solve {
  FortranInt iflag = 0, ierror = 0, negative = 0;  // of the factorisation
  FortranInt la = 0, liw = 0;                      // asked for by the analysis
  Eigen::VectorXd x;
};

Solve solve(const Triplets& t, const Eigen::VectorXd& b) {
  FortranInt n = t.n, nz = static_cast<FortranInt>(t.values.size());
  FortranInt icntl[30], info[20], iflag = 0, nsteps = 0, maxfrt = 0;
  double cntl[5], ops = 0.0;
  kkt::defaults(icntl, cntl);
  FortranInt liw = 2 * (2 * nz + 3 * n + 1);
  std::vector<FortranInt> iw(static_cast<std::size_t>(liw)), ikeep(3 * n), iw1(2 * n);
  kkt::analyse(&n, &nz, t.irn.data(), t.icn.data(), iw.data(), &liw, ikeep.data(), iw1.data(),
               &nsteps, &iflag, icntl, cntl, info, &ops);
  EXPECT_EQ(info[0], 0);
  Solve s;
  s.la = std::max(nz, info[4]);
  s.liw = info[5];
  liw = s.liw;
  FortranInt la = s.la;
  iw.assign(static_cast<std::size_t>(liw), 0);
  std::vector<double> a(static_cast<std::size_t>(la), 0.0);
  std::copy(t.values.begin(), t.values.end(), a.begin());
  kkt::factorise(&n, &nz, t.irn.data(), t.icn.data(), a.data(), &la, iw.data(), &liw, ikeep.data(),
                 &nsteps, &maxfrt, iw1.data(), icntl, cntl, info);
  s.iflag = info[0];
  s.ierror = info[1];
  s.negative = info[14];
  s.x = b;
  if (s.iflag == 0) {
    std::vector<double> w(static_cast<std::size_t>(maxfrt));
    std::vector<FortranInt> iw2(static_cast<std::size_t>(nsteps));
    kkt::solve(&n, a.data(), &la, iw.data(), &liw, w.data(), &maxfrt, s.x.data(), iw2.data(),
               &nsteps, icntl, cntl);
  }
  return s;
}

int negative_eigenvalues(const Eigen::MatrixXd& m) {
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues();
  return static_cast<int>((eigenvalues.array() < 0.0).count());
}

/// ‖A x - b‖∞ / (‖A‖∞ ‖x‖∞): Bunch–Kaufman's backward error is a modest multiple of n ε.
double relative_residual(const Eigen::MatrixXd& m,
                         const Eigen::VectorXd& x,
                         const Eigen::VectorXd& b) {
  const double norm_a = m.cwiseAbs().rowwise().sum().maxCoeff();
  return (m * x - b).lpNorm<Eigen::Infinity>() / (norm_a * x.lpNorm<Eigen::Infinity>());
}

Eigen::MatrixXd random_symmetric(int n, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd m(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i) m(i, j) = m(j, i) = uniform(random);
  return m;
}

Eigen::VectorXd random_vector(int n, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = uniform(random);
  return v;
}

TEST(DenseKktSolver, SolvesRandomIndefiniteMatricesWithTheirInertia) {
  std::mt19937 random(26);
  for (int n = 1; n <= 60; ++n) {
    const Eigen::MatrixXd m = random_symmetric(n, random);
    const Eigen::VectorXd b = random_vector(n, random);
    const Solve s = solve(lower_triangle(m), b);
    ASSERT_EQ(s.iflag, 0) << n;
    EXPECT_EQ(s.negative, negative_eigenvalues(m)) << n;
    EXPECT_LE(relative_residual(m, s.x, b), 4.0 * n * Eigen::NumTraits<double>::epsilon()) << n;
  }
}

TEST(DenseKktSolver, GivesAKktMatrixsInertia) {
  // [H Jᵀ; J -δ I]: H positive definite (6 × 6), J of full row rank: 6 positive, m negative.
  std::mt19937 random(7);
  for (int m : {1, 6, 20, 40}) {
    const Eigen::MatrixXd r = random_symmetric(6, random);
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(6 + m, 6 + m);
    k.topLeftCorner(6, 6) = r * r + 0.1 * Eigen::MatrixXd::Identity(6, 6);
    for (int i = 0; i < m; ++i) {
      const Eigen::VectorXd row = random_vector(6, random);
      k.block(6 + i, 0, 1, 6) = row.transpose();
      k.block(0, 6 + i, 6, 1) = row;
      k(6 + i, 6 + i) = m > 6 ? -1e-3 : 0.0;  // more rows than unknowns: regularised
    }
    const Eigen::VectorXd b = random_vector(6 + m, random);
    const Solve s = solve(lower_triangle(k), b);
    ASSERT_EQ(s.iflag, 0) << m;
    EXPECT_EQ(s.negative, m);
    EXPECT_EQ(s.negative, negative_eigenvalues(k));
    EXPECT_LE(relative_residual(k, s.x, b), 4.0 * (6 + m) * Eigen::NumTraits<double>::epsilon());
  }
}

TEST(DenseKktSolver, FlagsASingularMatrixWithItsRank) {
  std::mt19937 random(3);
  // B D Bᵀ with B of 12 × 7: rank 7, indefinite.
  Eigen::MatrixXd basis(12, 7);
  for (int j = 0; j < 7; ++j) basis.col(j) = random_vector(12, random);
  Eigen::VectorXd d(7);
  d << 1.0, -2.0, 0.5, 3.0, -1.0, 0.7, -0.4;
  const Eigen::MatrixXd m = basis * d.asDiagonal() * basis.transpose();
  Solve s = solve(lower_triangle(m), random_vector(12, random));
  EXPECT_EQ(s.iflag, 3);
  EXPECT_EQ(s.ierror, 7);
  // A KKT matrix with two equal constraint rows (dg/dw without full row rank, no regularisation).
  Eigen::MatrixXd k = Eigen::MatrixXd::Identity(8, 8);
  const Eigen::VectorXd row = random_vector(6, random);
  for (int i : {6, 7}) {
    k.block(i, 0, 1, 6) = row.transpose();
    k.block(0, i, 6, 1) = row;
    k(i, i) = 0.0;
  }
  s = solve(lower_triangle(k), random_vector(8, random));
  EXPECT_EQ(s.iflag, 3);
  EXPECT_EQ(s.ierror, 7);
  // The zero matrix (an empty row and column).
  s = solve(lower_triangle(Eigen::MatrixXd::Zero(3, 3)), random_vector(3, random));
  EXPECT_EQ(s.iflag, 3);
  EXPECT_EQ(s.ierror, 0);
}

TEST(DenseKktSolver, SumsDuplicatesAndReadsEitherTriangle) {
  std::mt19937 random(11);
  const Eigen::MatrixXd m = random_symmetric(9, random);
  const Eigen::VectorXd b = random_vector(9, random);
  // Every entry split in three parts, the off-diagonal ones given in the upper triangle and the
  // lower, in a shuffled order.
  Triplets t;
  t.n = 9;
  for (int j = 0; j < 9; ++j)
    for (int i = j; i < 9; ++i) {
      t.add(i, j, 0.25 * m(i, j));
      t.add(j, i, 0.5 * m(i, j));
      t.add(i, j, 0.25 * m(i, j));
    }
  std::vector<int> order(t.values.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::shuffle(order.begin(), order.end(), random);
  Triplets shuffled;
  shuffled.n = 9;
  for (int k : order) shuffled.add(t.irn[k] - 1, t.icn[k] - 1, t.values[k]);
  const Solve once = solve(lower_triangle(m), b), split = solve(shuffled, b);
  ASSERT_EQ(split.iflag, 0);
  EXPECT_EQ(split.negative, negative_eigenvalues(m));
  EXPECT_LE((split.x - once.x).lpNorm<Eigen::Infinity>(), 1e-12 * once.x.lpNorm<Eigen::Infinity>());
}

TEST(DenseKktSolver, AsksForMoreSpaceTheWayMa27Does) {
  std::mt19937 random(5);
  const Eigen::MatrixXd m = random_symmetric(10, random);
  const Triplets t = lower_triangle(m);
  FortranInt n = t.n, nz = static_cast<FortranInt>(t.values.size());
  FortranInt icntl[30], info[20], iflag = 0, nsteps = 0, maxfrt = 0;
  double cntl[5], ops = 0.0;
  kkt::defaults(icntl, cntl);
  std::vector<FortranInt> ikeep(3 * n), iw1(2 * n), iw(1000);
  FortranInt liw = 1000;
  kkt::analyse(&n, &nz, t.irn.data(), t.icn.data(), iw.data(), &liw, ikeep.data(), iw1.data(),
               &nsteps, &iflag, icntl, cntl, info, &ops);
  ASSERT_EQ(info[0], 0);
  const FortranInt la_needed = info[4], liw_needed = info[5];
  EXPECT_EQ(la_needed, nz + n * n + 2 * n);
  EXPECT_EQ(liw_needed, n + 1);
  // Too small an IW: -3 with the size needed; too small an A: -4.
  FortranInt la = la_needed, small_liw = liw_needed - 1;
  std::vector<double> a(static_cast<std::size_t>(la));
  std::copy(t.values.begin(), t.values.end(), a.begin());
  kkt::factorise(&n, &nz, t.irn.data(), t.icn.data(), a.data(), &la, iw.data(), &small_liw,
                 ikeep.data(), &nsteps, &maxfrt, iw1.data(), icntl, cntl, info);
  EXPECT_EQ(info[0], -3);
  EXPECT_EQ(info[1], liw_needed);
  FortranInt small_la = la_needed - 1;
  liw = liw_needed;
  kkt::factorise(&n, &nz, t.irn.data(), t.icn.data(), a.data(), &small_la, iw.data(), &liw,
                 ikeep.data(), &nsteps, &maxfrt, iw1.data(), icntl, cntl, info);
  EXPECT_EQ(info[0], -4);
  EXPECT_EQ(info[1], la_needed);
  // With the space asked for, and IPOPT's values untouched by the refusals.
  kkt::factorise(&n, &nz, t.irn.data(), t.icn.data(), a.data(), &la, iw.data(), &liw, ikeep.data(),
                 &nsteps, &maxfrt, iw1.data(), icntl, cntl, info);
  ASSERT_EQ(info[0], 0);
  EXPECT_EQ(info[14], negative_eigenvalues(m));
  Eigen::VectorXd x = random_vector(10, random);
  const Eigen::VectorXd b = x;
  std::vector<double> w(static_cast<std::size_t>(maxfrt));
  std::vector<FortranInt> iw2(static_cast<std::size_t>(nsteps));
  kkt::solve(&n, a.data(), &la, iw.data(), &liw, w.data(), &maxfrt, x.data(), iw2.data(), &nsteps,
             icntl, cntl);
  EXPECT_LE(relative_residual(m, x, b), 40.0 * Eigen::NumTraits<double>::epsilon());
  // The values are still IPOPT's, in a[0, nz).
  for (FortranInt k = 0; k < nz; ++k) EXPECT_EQ(a[static_cast<std::size_t>(k)], t.values[k]);
}

TEST(DenseKktSolver, AnalysisFlagsIndicesOutOfRange) {
  Triplets t = lower_triangle(Eigen::MatrixXd::Identity(3, 3));
  t.add(3, 0, 1.0);  // row 4 of 3
  FortranInt n = 3, nz = static_cast<FortranInt>(t.values.size());
  FortranInt icntl[30], info[20], iflag = 0, nsteps = 0, liw = 100;
  double cntl[5], ops = 0.0;
  kkt::defaults(icntl, cntl);
  std::vector<FortranInt> iw(100), ikeep(9), iw1(6);
  kkt::analyse(&n, &nz, t.irn.data(), t.icn.data(), iw.data(), &liw, ikeep.data(), iw1.data(),
               &nsteps, &iflag, icntl, cntl, info, &ops);
  EXPECT_EQ(info[0], 1);
  EXPECT_EQ(info[1], 1);
}

}  // namespace
}  // namespace test_dense_kkt_solver
}  // namespace rodshape
