#include <cairn/planning/stabilization/discrete_riccati.h>

#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cairn/common/number_text.h>

namespace cairn::planning {

Eigen::MatrixXd SolveDiscreteAlgebraicRiccati(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                              const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R) {
  const Eigen::Index n = A.rows(), m = B.cols();
  if (A.cols() != n || B.rows() != n || Q.rows() != n || Q.cols() != n || R.rows() != m || R.cols() != m || n == 0 ||
      m == 0) {
    throw std::invalid_argument("SolveDiscreteAlgebraicRiccati: sizes do not match (A " + std::to_string(A.rows()) +
                                "x" + std::to_string(A.cols()) + ", B " + std::to_string(B.rows()) + "x" +
                                std::to_string(B.cols()) + ", Q " + std::to_string(Q.rows()) + "x" +
                                std::to_string(Q.cols()) + ", R " + std::to_string(R.rows()) + "x" +
                                std::to_string(R.cols()) + "); A and Q must be n x n, B n x m, R m x m");
  }
  if (!A.allFinite() || !B.allFinite() || !Q.allFinite() || !R.allFinite()) {
    throw std::invalid_argument("SolveDiscreteAlgebraicRiccati: a matrix has an entry that is not finite");
  }
  if (!Q.isApprox(Q.transpose(), 1e-12) ||
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Q).eigenvalues().minCoeff() < -1e-12 * (1.0 + Q.norm())) {
    throw std::invalid_argument("SolveDiscreteAlgebraicRiccati: Q must be symmetric positive semidefinite");
  }
  const Eigen::LLT<Eigen::MatrixXd> r_llt(R);
  if (!R.isApprox(R.transpose(), 1e-12) || r_llt.info() != Eigen::Success) {
    throw std::invalid_argument("SolveDiscreteAlgebraicRiccati: R must be symmetric positive definite");
  }
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd a = A, g = B * r_llt.solve(B.transpose()), h = Q;
  for (int k = 0; k < 100; ++k) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> w(identity + g * h);
    const Eigen::MatrixXd wa = w.solve(a);
    const Eigen::MatrixXd h_next = h + a.transpose() * h * wa;
    const Eigen::MatrixXd g_next = g + a * w.solve(g) * a.transpose();
    a = a * wa;
    const double change = (h_next - h).cwiseAbs().maxCoeff();  // norm() overflows above 1e154
    h = 0.5 * (h_next + h_next.transpose());
    g = 0.5 * (g_next + g_next.transpose());
    if (!h.allFinite()) break;
    if (change <= 1e-12 * (1.0 + h.cwiseAbs().maxCoeff())) return h;
  }
  throw std::runtime_error("SolveDiscreteAlgebraicRiccati: the doubling iteration did not converge in 100 steps; "
                           "(A, B) must be stabilisable and (A, Q) detectable");
}

}  // namespace cairn::planning
