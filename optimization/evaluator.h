#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace cairn::optimization {

class ProgramAssembly;

/// One structurally nonzero entry of a sparse derivative: row (output, or first variable for a Hessian) and
/// column (input variable), both local to the evaluator.
struct SparsityEntry {
  int row{0};  ///< Output index (Jacobian) or the larger variable index (Hessian lower triangle).
  int col{0};  ///< Input variable index.
};

/// Where an evaluator's Jacobian comes from; CheckGradients reports it so a failing entry can be traced.
enum class DerivativeSource {
  kAnalytic,          ///< Hand-written derivatives (DoEvalWithJacobian overridden).
  kAutoDiff,          ///< Eigen AutoDiffScalar forward mode (AutoDiffEvaluator).
  kFiniteDifference,  ///< Central finite differences over the declared pattern (the fallback).
};

/// Returns "analytic", "autodiff" or "finite differences".
const char* to_string(DerivativeSource source);

/// A vector function y = f(x) of a fixed number of inputs and outputs, the building block of every cost and
/// constraint of a MathematicalProgram.
///
/// Two evaluation paths: value-only (`Eval`) and value plus a sparse Jacobian (`EvalWithJacobian`). The
/// Jacobian's nonzero pattern is declared once, at construction, as (output, input) pairs; `EvalWithJacobian`
/// writes one value per pattern entry, in pattern order. Solvers assemble their global sparse structure from
/// these patterns once and never ask again (Ipopt fixes its structure at the first call). Optionally an evaluator
/// declares the lower triangle of its Hessian pattern and provides `EvalHessian`, the weighted sum of its
/// outputs' Hessians; Ipopt uses exact Hessians only when every term of a program provides one.
///
/// Evaluators are immutable after construction and their const methods must be safe to call from several
/// threads at once (no mutable state), because one program may be solved on several threads.
///
/// Subclasses implement DoEval and, for analytic derivatives, DoEvalWithJacobian; the default
/// DoEvalWithJacobian computes central finite differences over the declared pattern.
class Evaluator {
 public:
  virtual ~Evaluator();
  Evaluator(const Evaluator&) = delete;
  Evaluator& operator=(const Evaluator&) = delete;

  /// Name used in every message about this evaluator (e.g. "com_in_support_polygon").
  const std::string& name() const { return name_; }
  /// Number of inputs (the size of x).
  int num_inputs() const { return num_inputs_; }
  /// Number of outputs (the size of y).
  int num_outputs() const { return num_outputs_; }
  /// The Jacobian's nonzero pattern, in the order EvalWithJacobian writes values.
  const std::vector<SparsityEntry>& jacobian_pattern() const { return jacobian_pattern_; }
  /// Number of structurally nonzero Jacobian entries.
  int jacobian_nonzeros() const { return static_cast<int>(jacobian_pattern_.size()); }
  /// How the Jacobian is computed.
  DerivativeSource jacobian_source() const { return jacobian_source_; }
  /// True if EvalHessian is available.
  bool has_hessian() const { return has_hessian_; }
  /// Lower-triangle (row >= col) Hessian pattern, in the order EvalHessian writes values.
  const std::vector<SparsityEntry>& hessian_pattern() const { return hessian_pattern_; }

  /// Computes y = f(x). Throws std::invalid_argument if a size is wrong.
  void Eval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const;

  /// Convenience form of Eval that allocates its result.
  Eigen::VectorXd Eval(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// Computes y = f(x) and the Jacobian values, one per jacobian_pattern() entry.
  void EvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                        Eigen::Ref<Eigen::VectorXd> jacobian_values) const;

  /// Convenience: the Jacobian at x as a num_outputs() x num_inputs() sparse matrix (allocates).
  Eigen::SparseMatrix<double> EvalJacobian(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// Computes sum_k weights(k) * Hessian(f_k)(x), one value per hessian_pattern() entry. Throws
  /// std::logic_error if !has_hessian().
  void EvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                   Eigen::Ref<Eigen::VectorXd> hessian_values) const;

  /// The dense pattern of a rows x cols Jacobian, row-major.
  static std::vector<SparsityEntry> DensePattern(int rows, int cols);

 protected:
  /// Declares the evaluator's shape and Jacobian pattern. Throws std::invalid_argument naming the evaluator if
  /// a size is negative or a pattern entry is out of range or repeated.
  Evaluator(std::string name, int num_inputs, int num_outputs, std::vector<SparsityEntry> jacobian_pattern,
            DerivativeSource jacobian_source);

  /// Declares that DoEvalHessian is implemented, with this lower-triangle pattern (may be empty for linear
  /// functions). Call from the subclass constructor only.
  void DeclareHessianPattern(std::vector<SparsityEntry> hessian_pattern);

  /// Computes y = f(x); sizes are already checked.
  virtual void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const = 0;

  /// Computes y and the Jacobian values; the default uses central finite differences.
  virtual void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                  Eigen::Ref<Eigen::VectorXd> jacobian_values) const;

  /// Computes the weighted Hessian values; only called if DeclareHessianPattern was called.
  virtual void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                             const Eigen::Ref<const Eigen::VectorXd>& weights,
                             Eigen::Ref<Eigen::VectorXd> hessian_values) const;

  /// Central finite differences of DoEval over the declared pattern (step cbrt(eps) * max(1, |x_j|)). Uses
  /// per-thread scratch buffers, so steady-state calls do not allocate.
  void FiniteDifferenceJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                Eigen::Ref<Eigen::VectorXd> jacobian_values) const;

 private:
  // The solvers' evaluation loop calls the Do* hooks directly: its buffers are sized from the declared shapes
  // once, so the per-call size checks of the public methods would only cost time in the hot path.
  friend class ProgramAssembly;

  void CheckInputSize(const Eigen::Ref<const Eigen::VectorXd>& x, const char* method) const;

  std::string name_;
  int num_inputs_{0};
  int num_outputs_{0};
  std::vector<SparsityEntry> jacobian_pattern_;
  DerivativeSource jacobian_source_;
  bool has_hessian_{false};
  std::vector<SparsityEntry> hessian_pattern_;
  // Pattern entries grouped by column, for finite differences: entries column_order_[column_starts_[k] ..
  // column_starts_[k + 1]) share column fd_columns_[k].
  std::vector<int> fd_columns_;
  std::vector<int> column_starts_;
  std::vector<int> column_order_;
};

}  // namespace cairn::optimization
