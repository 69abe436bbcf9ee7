// cairn.optimization: MathematicalProgram, evaluators (C++ and Python callables), solvers and results.
//
// Solve() releases the GIL; evaluators made from Python callables take it for each evaluation, so a Python cost
// works inside Ipopt, NLopt or the least-squares solver while other Python threads keep running between its calls.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cairn/common/number_text.h"
#include "cairn/optimization/binding.h"
#include "cairn/optimization/bounding_box_constraint.h"
#include "cairn/optimization/check_gradients.h"
#include "cairn/optimization/constraint.h"
#include "cairn/optimization/decision_variables.h"
#include "cairn/optimization/evaluator.h"
#include "cairn/optimization/evaluator_constraint.h"
#include "cairn/optimization/function_evaluator.h"
#include "cairn/optimization/linear_constraint.h"
#include "cairn/optimization/linear_cost.h"
#include "cairn/optimization/linear_equality_constraint.h"
#include "cairn/optimization/mathematical_program.h"
#include "cairn/optimization/quadratic_cost.h"
#include "cairn/optimization/solve.h"
#include "cairn/optimization/solvers/ipopt_solver.h"
#include "cairn/optimization/solvers/least_squares_solver.h"
#include "cairn/optimization/solvers/make_solver.h"
#include "cairn/optimization/solvers/nlopt_solver.h"
#include "cairn/optimization/solvers/solver.h"
#include "cairn/optimization/solvers/solver_options.h"
#include "cairn/optimization/solvers/solver_result.h"
#include "numpy_support.h"
#include "python_object.h"

namespace cairn::python {

using namespace cairn::optimization;

namespace {

std::vector<SparsityEntry> PatternFromPython(const std::vector<std::pair<int, int>>& entries) {
  std::vector<SparsityEntry> pattern;
  pattern.reserve(entries.size());
  for (const auto& [row, col] : entries) pattern.push_back({row, col});
  return pattern;
}

py::list PatternToPython(const std::vector<SparsityEntry>& pattern) {
  py::list out;
  for (const SparsityEntry& e : pattern) out.append(py::make_tuple(e.row, e.col));
  return out;
}

// A Python result converted to `size` values; a float counts as one value. `what` names the callable.
Eigen::VectorXd ValuesFromPython(const py::object& result, Eigen::Index size, const std::string& what) {
  Eigen::VectorXd values;
  if (PyFloat_Check(result.ptr()) || PyLong_Check(result.ptr())) {
    values = Eigen::VectorXd::Constant(1, result.cast<double>());
  } else {
    values = result.cast<Eigen::VectorXd>();
  }
  if (values.size() != size) {
    throw std::invalid_argument(what + " returned " + cairn::FormatShort(values.size()) + " values, expected " +
                                cairn::FormatShort(size));
  }
  return values;
}

// Jacobian (or Hessian) values in pattern order from what a Python callable returned: a 1-D array of one value
// per pattern entry, or a dense 2-D (rows x cols) matrix read at the pattern entries.
void PatternValuesFromPython(const py::object& result, const std::vector<SparsityEntry>& pattern, Eigen::Index rows,
                             Eigen::Index cols, const std::string& what, Eigen::Ref<Eigen::VectorXd> values) {
  const auto array = py::array_t<double, py::array::forcecast>::ensure(result);
  if (!array) throw std::invalid_argument(what + " must return an array");
  if (array.ndim() == 1) {
    if (array.shape(0) != static_cast<py::ssize_t>(pattern.size())) {
      throw std::invalid_argument(what + " returned " + cairn::FormatShort(array.shape(0)) +
                                  " values, expected one per pattern entry (" + cairn::FormatShort(pattern.size()) +
                                  ") or a " + cairn::FormatShort(rows) + " x " + cairn::FormatShort(cols) + " matrix");
    }
    auto view = array.unchecked<1>();
    for (std::size_t k = 0; k < pattern.size(); ++k) values[static_cast<Eigen::Index>(k)] = view(static_cast<py::ssize_t>(k));
    return;
  }
  if (array.ndim() != 2 || array.shape(0) != rows || array.shape(1) != cols) {
    throw std::invalid_argument(what + " returned an array of shape " + std::string(py::str(array.attr("shape"))) +
                                ", expected (" + cairn::FormatShort(rows) + ", " + cairn::FormatShort(cols) + ")");
  }
  auto view = array.unchecked<2>();
  for (std::size_t k = 0; k < pattern.size(); ++k) values[static_cast<Eigen::Index>(k)] = view(pattern[k].row, pattern[k].col);
}

// A FunctionEvaluator over Python callables (see the FunctionEvaluator binding's docstring).
std::shared_ptr<FunctionEvaluator> MakePythonEvaluator(const std::string& name, int num_inputs, int num_outputs,
                                               py::object value, py::object jacobian,
                                               std::optional<std::vector<std::pair<int, int>>> jacobian_pattern,
                                               py::object hessian,
                                               std::optional<std::vector<std::pair<int, int>>> hessian_pattern) {
  if (!PyCallable_Check(value.ptr())) throw py::type_error("FunctionEvaluator '" + name + "': value is not callable");
  const std::vector<SparsityEntry> pattern = jacobian_pattern ? PatternFromPython(*jacobian_pattern)
                                                              : Evaluator::DensePattern(num_outputs, num_inputs);
  SharedPyObject value_fn(std::move(value));
  FunctionEvaluator::ValueFunction value_function =
      [value_fn, num_outputs, name](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) {
        py::gil_scoped_acquire gil;
        y = ValuesFromPython(value_fn.get()(CallbackConstVectorView(x.data(), x.size())), num_outputs,
                             "the value function of '" + name + "'");
      };
  FunctionEvaluator::JacobianFunction jacobian_function;
  if (!jacobian.is_none()) {
    SharedPyObject jacobian_fn(std::move(jacobian));
    jacobian_function = [jacobian_fn, pattern, num_inputs, num_outputs, name](
                            const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                            Eigen::Ref<Eigen::VectorXd> values) {
      py::gil_scoped_acquire gil;
      py::object result = jacobian_fn.get()(CallbackConstVectorView(x.data(), x.size()));
      const std::string what = "the jacobian function of '" + name + "'";
      py::tuple pair;
      try {
        pair = result.cast<py::tuple>();
      } catch (const py::cast_error&) {
        throw std::invalid_argument(what + " must return (value, jacobian)");
      }
      if (pair.size() != 2) throw std::invalid_argument(what + " must return (value, jacobian)");
      y = ValuesFromPython(pair[0], num_outputs, what + " (value)");
      PatternValuesFromPython(pair[1], pattern, num_outputs, num_inputs, what, values);
    };
  }
  std::vector<SparsityEntry> hessian_entries;
  FunctionEvaluator::HessianFunction hessian_function;
  if (!hessian.is_none()) {
    if (!hessian_pattern) {
      for (int row = 0; row < num_inputs; ++row) {
        for (int col = 0; col <= row; ++col) hessian_entries.push_back({row, col});
      }
    } else {
      hessian_entries = PatternFromPython(*hessian_pattern);
    }
    SharedPyObject hessian_fn(std::move(hessian));
    hessian_function = [hessian_fn, hessian_entries, num_inputs, name](const Eigen::Ref<const Eigen::VectorXd>& x,
                                                                       const Eigen::Ref<const Eigen::VectorXd>& w,
                                                                       Eigen::Ref<Eigen::VectorXd> values) {
      py::gil_scoped_acquire gil;
      py::object result = hessian_fn.get()(CallbackConstVectorView(x.data(), x.size()),
                                           CallbackConstVectorView(w.data(), w.size()));
      PatternValuesFromPython(result, hessian_entries, num_inputs, num_inputs,
                              "the hessian function of '" + name + "'", values);
    };
  }
  return std::make_shared<FunctionEvaluator>(name, num_inputs, num_outputs, pattern, std::move(value_function),
                                             std::move(jacobian_function), std::move(hessian_entries),
                                             std::move(hessian_function));
}

// A scalar cost from f(x) -> float and an optional gradient g(x) -> array of n.
std::shared_ptr<Evaluator> MakePythonCost(const std::string& name, int n, py::object function, py::object gradient) {
  if (gradient.is_none()) return MakePythonEvaluator(name, n, 1, std::move(function), py::none(), {}, py::none(), {});
  // One Python call for the value and one for the gradient, per evaluation with derivatives.
  py::object f = function;
  py::object g = gradient;
  py::cpp_function both([f, g](py::object x) { return py::make_tuple(f(x), g(x)); });
  return MakePythonEvaluator(name, n, 1, std::move(function), both, {}, py::none(), {});
}

// A vector function from f(x) -> array of m and an optional dense Jacobian J(x) -> (m, n) array.
std::shared_ptr<Evaluator> MakePythonFunction(const std::string& name, int n, int m, py::object function,
                                              py::object jacobian) {
  if (jacobian.is_none()) return MakePythonEvaluator(name, n, m, std::move(function), py::none(), {}, py::none(), {});
  py::object f = function;
  py::object j = jacobian;
  py::cpp_function both([f, j](py::object x) { return py::make_tuple(f(x), j(x)); });
  return MakePythonEvaluator(name, n, m, std::move(function), both, {}, py::none(), {});
}

Eigen::SparseMatrix<double> ToSparse(const Eigen::Ref<const Eigen::MatrixXd>& dense) { return dense.sparseView(); }

py::tuple ResultState(const SolverResult& r) {
  return py::make_tuple(r.solver_name, r.status, r.x, r.objective, r.constraint_violation, r.constraint_duals,
                        r.bound_duals, r.iterations, r.evaluations, r.wall_time_seconds, r.message);
}

SolverResult ResultFromState(const py::tuple& t) {
  if (t.size() != 11) throw std::runtime_error("SolverResult: bad pickle state");
  SolverResult r;
  r.solver_name = t[0].cast<std::string>();
  r.status = t[1].cast<SolutionStatus>();
  r.x = t[2].cast<Eigen::VectorXd>();
  r.objective = t[3].cast<double>();
  r.constraint_violation = t[4].cast<double>();
  r.constraint_duals = t[5].cast<Eigen::VectorXd>();
  r.bound_duals = t[6].cast<Eigen::VectorXd>();
  r.iterations = t[7].cast<int>();
  r.evaluations = t[8].cast<int>();
  r.wall_time_seconds = t[9].cast<double>();
  r.message = t[10].cast<std::string>();
  return r;
}

SolverResult SolveWith(const Solver& solver, const MathematicalProgram& prog,
                       const std::optional<Eigen::VectorXd>& initial_guess, const std::optional<SolverOptions>& options) {
  const Eigen::VectorXd guess = initial_guess ? *initial_guess : prog.initial_guess();
  const SolverOptions opts = options ? *options : SolverOptions();
  py::gil_scoped_release release;
  return solver.Solve(prog, guess, opts);
}

}  // namespace

void DefineOptimization(py::module_ m) {
  py::enum_<DerivativeSource>(m, "DerivativeSource", "Where an evaluator's Jacobian comes from.")
      .value("kAnalytic", DerivativeSource::kAnalytic, "Hand-written derivatives.")
      .value("kAutoDiff", DerivativeSource::kAutoDiff, "Eigen AutoDiffScalar forward mode.")
      .value("kFiniteDifference", DerivativeSource::kFiniteDifference, "Central finite differences (the fallback).");

  py::class_<DecisionVariables>(m, "DecisionVariables",
                                "An ordered list of a program's decision variables, for binding costs and "
                                "constraints. x[i] is the i-th variable (as a one-variable list), x[a:b] a segment.")
      .def(py::init<>(), "An empty list that belongs to no program.")
      .def("size", &DecisionVariables::size, "Number of variables.")
      .def("__len__", &DecisionVariables::size, "Number of variables.")
      .def("empty", &DecisionVariables::empty, "True if the list is empty.")
      .def(
          "__getitem__",
          [](const DecisionVariables& self, int i) {
            if (i < 0) i += self.size();
            if (i < 0 || i >= self.size()) throw py::index_error("variable index out of range");
            return self.Element(i);
          },
          py::arg("i"), "The i-th variable (negative counts from the end), as a one-variable list.")
      .def(
          "__getitem__",
          [](const DecisionVariables& self, const py::slice& slice) {
            py::ssize_t start = 0, stop = 0, step = 0, length = 0;
            if (!slice.compute(self.size(), &start, &stop, &step, &length)) throw py::error_already_set();
            if (step != 1) throw py::value_error("DecisionVariables slices must have step 1");
            return self.Segment(static_cast<int>(start), static_cast<int>(length));
          },
          py::arg("slice"), "The variables of a contiguous slice.")
      .def("indices", &DecisionVariables::indices, "Indices into the program's decision vector, in list order.")
      .def("index", &DecisionVariables::operator[], py::arg("i"), "Index into the decision vector of variable i.")
      .def("description", &DecisionVariables::description, "Description used in messages, e.g. \"x[2:4]\".")
      .def("program_id", &DecisionVariables::program_id, "Identifier of the program that made the variables.")
      .def("Segment", &DecisionVariables::Segment, py::arg("start"), py::arg("count"),
           "The `count` variables from list position `start`.")
      .def("Element", &DecisionVariables::Element, py::arg("i"), "Variable i as a one-variable list.")
      .def_static("Concatenate", &DecisionVariables::Concatenate, py::arg("parts"),
                  "The lists joined in order (all of one program).")
      .def("__repr__", [](const DecisionVariables& self) { return "<DecisionVariables " + self.description() + ">"; },
           "<DecisionVariables x[...]>.");

  py::class_<Evaluator, std::shared_ptr<Evaluator>>(
      m, "Evaluator",
      "A vector function y = f(x) with a sparse Jacobian of declared pattern: the building block of costs and "
      "constraints. Make one from Python callables with FunctionEvaluator.")
      .def("name", &Evaluator::name, "Name used in messages.")
      .def("num_inputs", &Evaluator::num_inputs, "Size of x.")
      .def("num_outputs", &Evaluator::num_outputs, "Size of y.")
      .def("jacobian_pattern", [](const Evaluator& self) { return PatternToPython(self.jacobian_pattern()); },
           "The Jacobian's structural nonzeros as (output, input) pairs, in the order values are written.")
      .def("jacobian_nonzeros", &Evaluator::jacobian_nonzeros, "Number of Jacobian nonzeros.")
      .def("jacobian_source", &Evaluator::jacobian_source, "How the Jacobian is computed.")
      .def("has_hessian", &Evaluator::has_hessian, "True if EvalHessian is available.")
      .def("hessian_pattern", [](const Evaluator& self) { return PatternToPython(self.hessian_pattern()); },
           "Lower-triangle Hessian pattern as (row, col) pairs.")
      .def(
          "Eval",
          [](const Evaluator& self, const Eigen::Ref<const Eigen::VectorXd>& x) { return self.Eval(x); },
          py::arg("x"), "y = f(x); ValueError on a wrong size.")
      .def(
          "EvalWithJacobian",
          [](const Evaluator& self, const Eigen::Ref<const Eigen::VectorXd>& x) {
            Eigen::VectorXd y(self.num_outputs());
            Eigen::VectorXd values(self.jacobian_nonzeros());
            self.EvalWithJacobian(x, y, values);
            return py::make_tuple(y, values);
          },
          py::arg("x"), "(y, Jacobian values in pattern order).")
      .def(
          "EvalJacobian",
          [](const Evaluator& self, const Eigen::Ref<const Eigen::VectorXd>& x) {
            return Eigen::MatrixXd(self.EvalJacobian(x));
          },
          py::arg("x"), "The Jacobian at x as a dense num_outputs x num_inputs array.")
      .def(
          "EvalHessian",
          [](const Evaluator& self, const Eigen::Ref<const Eigen::VectorXd>& x,
             const Eigen::Ref<const Eigen::VectorXd>& weights) {
            Eigen::VectorXd values(static_cast<Eigen::Index>(self.hessian_pattern().size()));
            self.EvalHessian(x, weights, values);
            return values;
          },
          py::arg("x"), py::arg("weights"),
          "sum_k weights[k] Hessian(f_k)(x), one value per hessian_pattern() entry; raises if !has_hessian().")
      .def_static("DensePattern", [](int rows, int cols) { return PatternToPython(Evaluator::DensePattern(rows, cols)); },
                  py::arg("rows"), py::arg("cols"), "The dense pattern of a rows x cols Jacobian, row-major.")
      .def("__repr__", [](const Evaluator& self) {
        return "<Evaluator '" + self.name() + "' " + cairn::FormatShort(self.num_inputs()) + " -> " +
               cairn::FormatShort(self.num_outputs()) + ">";
      }, "<Evaluator 'name' n -> m>.");

  py::class_<FunctionEvaluator, Evaluator, std::shared_ptr<FunctionEvaluator>>(
      m, "FunctionEvaluator",
      "An Evaluator made of Python callables. value(x) returns y (array-like of num_outputs; a float when "
      "num_outputs is 1). jacobian(x), optional, returns (y, J) with J either one value per pattern entry or a dense "
      "(num_outputs, num_inputs) array; without it the Jacobian comes from central finite differences. "
      "hessian(x, w), optional, returns sum_k w_k Hessian(f_k) as one value per lower-triangle pattern entry or a "
      "dense symmetric matrix. x and w are read-only views valid during the call. Solvers call these with the GIL "
      "taken.")
      .def(py::init(&MakePythonEvaluator), py::arg("name"), py::arg("num_inputs"), py::arg("num_outputs"),
           py::arg("value"), py::arg("jacobian") = py::none(), py::arg("jacobian_pattern") = py::none(),
           py::arg("hessian") = py::none(), py::arg("hessian_pattern") = py::none(),
           "Patterns are lists of (row, col) pairs (default: dense Jacobian, full lower-triangle Hessian).");

  py::class_<LinearCost, Evaluator, std::shared_ptr<LinearCost>>(m, "LinearCost", "The cost a'x + b.")
      .def(py::init<const Eigen::Ref<const Eigen::VectorXd>&, double>(), py::arg("a"), py::arg("b"),
           "ValueError if a or b is not finite.")
      .def("a", [](const LinearCost& self) { return Eigen::VectorXd(self.a()); }, "Coefficients a.")
      .def("b", &LinearCost::b, "Constant term b.");

  py::class_<QuadraticCost, Evaluator, std::shared_ptr<QuadraticCost>>(
      m, "QuadraticCost", "The cost 1/2 x'Qx + b'x + c with a symmetric Q (stored sparse; exact Hessian).")
      .def(py::init([](const Eigen::Ref<const Eigen::MatrixXd>& Q, const Eigen::Ref<const Eigen::VectorXd>& b,
                       double c) { return std::make_shared<QuadraticCost>(ToSparse(Q), b, c); }),
           py::arg("Q"), py::arg("b"), py::arg("c"),
           "Q as a dense array (its zeros are dropped); ValueError unless square, symmetric and finite.")
      .def("Q", [](const QuadraticCost& self) { return Eigen::MatrixXd(self.Q()); }, "Q as a dense array.")
      .def("b", [](const QuadraticCost& self) { return Eigen::VectorXd(self.b()); }, "Linear coefficients b.")
      .def("c", &QuadraticCost::c, "Constant term c.");

  py::class_<Constraint, Evaluator, std::shared_ptr<Constraint>>(m, "Constraint",
                                                                 "An Evaluator with bounds: lb <= f(x) <= ub.")
      .def("lower_bound", [](const Constraint& self) { return Eigen::VectorXd(self.lower_bound()); }, "Lower bounds.")
      .def("upper_bound", [](const Constraint& self) { return Eigen::VectorXd(self.upper_bound()); }, "Upper bounds.")
      .def("Violation", &Constraint::Violation, py::arg("x"), "Largest violation max(lb - y, y - ub, 0).");

  py::class_<LinearConstraint, Constraint, std::shared_ptr<LinearConstraint>>(
      m, "LinearConstraint", "lb <= A x <= ub (A stored sparse).")
      .def(py::init([](const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::VectorXd>& lb,
                       const Eigen::Ref<const Eigen::VectorXd>& ub) {
             return std::make_shared<LinearConstraint>(ToSparse(A), lb, ub);
           }),
           py::arg("A"), py::arg("lb"), py::arg("ub"), "A as a dense array (its zeros are dropped).")
      .def("A", [](const LinearConstraint& self) { return Eigen::MatrixXd(self.A()); }, "A as a dense array.");

  py::class_<LinearEqualityConstraint, LinearConstraint, std::shared_ptr<LinearEqualityConstraint>>(
      m, "LinearEqualityConstraint", "A x = b.")
      .def(py::init([](const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::VectorXd>& b) {
             return std::make_shared<LinearEqualityConstraint>(ToSparse(A), b);
           }),
           py::arg("A"), py::arg("b"), "A as a dense array.")
      .def("b", [](const LinearEqualityConstraint& self) { return Eigen::VectorXd(self.b()); }, "Right-hand side.");

  py::class_<BoundingBoxConstraint, LinearConstraint, std::shared_ptr<BoundingBoxConstraint>>(
      m, "BoundingBoxConstraint", "lb <= x <= ub on the bound variables (solvers fold it into variable bounds).")
      .def(py::init<const Eigen::Ref<const Eigen::VectorXd>&, const Eigen::Ref<const Eigen::VectorXd>&>(),
           py::arg("lb"), py::arg("ub"), "ValueError for differing sizes, NaN or lb > ub.");

  py::class_<EvaluatorConstraint, Constraint, std::shared_ptr<EvaluatorConstraint>>(
      m, "EvaluatorConstraint", "The nonlinear constraint lb <= f(x) <= ub around any Evaluator.")
      .def(py::init([](std::shared_ptr<Evaluator> evaluator, const Eigen::Ref<const Eigen::VectorXd>& lb,
                       const Eigen::Ref<const Eigen::VectorXd>& ub) {
             return std::make_shared<EvaluatorConstraint>(std::move(evaluator), lb, ub);
           }),
           py::arg("evaluator"), py::arg("lb"), py::arg("ub"), "ValueError if the bounds do not match its outputs.");

  py::class_<Binding<Evaluator>>(m, "Binding", "An evaluator bound to an ordered list of decision variables.")
      .def("evaluator", &Binding<Evaluator>::evaluator, "The bound evaluator.")
      .def("variables", &Binding<Evaluator>::variables, "The variables, one per evaluator input.")
      .def("ToString", &Binding<Evaluator>::ToString, "\"name(variables)\".")
      .def("__repr__", [](const Binding<Evaluator>& b) { return "<Binding " + b.ToString() + ">"; }, "<Binding ...>.");
  py::class_<Binding<Constraint>>(m, "ConstraintBinding", "A constraint bound to decision variables.")
      .def("evaluator", &Binding<Constraint>::evaluator, "The bound constraint.")
      .def("variables", &Binding<Constraint>::variables, "The variables, one per constraint input.")
      .def("ToString", &Binding<Constraint>::ToString, "\"name(variables)\".")
      .def("__repr__", [](const Binding<Constraint>& b) { return "<ConstraintBinding " + b.ToString() + ">"; },
           "<ConstraintBinding ...>.");

  py::class_<MathematicalProgram>(
      m, "MathematicalProgram",
      "Minimise the sum of the costs over the decision variables subject to every constraint lb <= f(x) <= ub. "
      "Costs and constraints are C++ evaluators or Python callables. Solving never modifies the program.")
      .def(py::init<>(), "An empty program.")
      .def("NewContinuousVariables", &MathematicalProgram::NewContinuousVariables, py::arg("n"), py::arg("name"),
           "Adds n variables name(0) .. name(n-1) (initial guess 0, no bounds); ValueError for n < 1 or a taken name.")
      .def("num_vars", &MathematicalProgram::num_vars, "Number of decision variables.")
      .def("VariableName", &MathematicalProgram::VariableName, py::arg("index"), "Name of a variable, e.g. \"q(3)\".")
      .def("variable_blocks", &MathematicalProgram::variable_blocks, "Every variable block, in creation order.")
      .def("GetVariables", &MathematicalProgram::GetVariables, py::arg("name"),
           "A block by name; ValueError listing the closest names.")
      .def("SetInitialGuess", &MathematicalProgram::SetInitialGuess, py::arg("vars"), py::arg("values"),
           "Sets the initial guess of `vars`.")
      .def("initial_guess", [](const MathematicalProgram& self) { return Eigen::VectorXd(self.initial_guess()); },
           "The initial guess of every variable.")
      .def("AddCost", &MathematicalProgram::AddCost, py::arg("cost"), py::arg("vars"),
           "Adds a scalar cost Evaluator bound to `vars`.")
      .def(
          "AddCost",
          [](MathematicalProgram& self, py::object function, const DecisionVariables& vars, py::object gradient,
             const std::string& name) {
            return self.AddCost(MakePythonCost(name, vars.size(), std::move(function), std::move(gradient)), vars);
          },
          py::arg("function"), py::arg("vars"), py::arg("gradient") = py::none(), py::arg("name") = "python_cost",
          "Adds the cost function(x) -> float over `vars`, with gradient(x) -> array (analytic) or finite "
          "differences.")
      .def(
          "AddLinearCost",
          [](MathematicalProgram& self, const Eigen::Ref<const Eigen::VectorXd>& a, double b,
             const DecisionVariables& vars) { return Binding<Evaluator>(self.AddLinearCost(a, b, vars)); },
          py::arg("a"), py::arg("b"), py::arg("vars"), "Adds a'x + b.")
      .def(
          "AddQuadraticCost",
          [](MathematicalProgram& self, const Eigen::Ref<const Eigen::MatrixXd>& Q,
             const Eigen::Ref<const Eigen::VectorXd>& b, double c, const DecisionVariables& vars) {
            return Binding<Evaluator>(self.AddQuadraticCost(ToSparse(Q), b, c, vars));
          },
          py::arg("Q"), py::arg("b"), py::arg("c"), py::arg("vars"), "Adds 1/2 x'Qx + b'x + c (Q dense, symmetric).")
      .def("AddLeastSquaresCost", &MathematicalProgram::AddLeastSquaresCost, py::arg("residual"), py::arg("vars"),
           "Adds 1/2 ||r(x)||^2 for a residual Evaluator.")
      .def(
          "AddLeastSquaresCost",
          [](MathematicalProgram& self, py::object function, const DecisionVariables& vars, int num_residuals,
             py::object jacobian, const std::string& name) {
            return self.AddLeastSquaresCost(
                MakePythonFunction(name, vars.size(), num_residuals, std::move(function), std::move(jacobian)), vars);
          },
          py::arg("function"), py::arg("vars"), py::arg("num_residuals"), py::arg("jacobian") = py::none(),
          py::arg("name") = "python_residual",
          "Adds 1/2 ||r(x)||^2 for r = function(x) (array of num_residuals), with jacobian(x) -> dense array or "
          "finite differences.")
      .def("AddConstraint",
           py::overload_cast<std::shared_ptr<Evaluator>, const Eigen::Ref<const Eigen::VectorXd>&,
                             const Eigen::Ref<const Eigen::VectorXd>&, const DecisionVariables&>(
               &MathematicalProgram::AddConstraint),
           py::arg("function"), py::arg("lb"), py::arg("ub"), py::arg("vars"), "Adds lb <= f(x) <= ub.")
      .def("AddConstraint",
           py::overload_cast<std::shared_ptr<Constraint>, const DecisionVariables&>(&MathematicalProgram::AddConstraint),
           py::arg("constraint"), py::arg("vars"), "Adds a built constraint (bounding boxes become variable bounds).")
      .def(
          "AddConstraint",
          [](MathematicalProgram& self, py::object function, const Eigen::Ref<const Eigen::VectorXd>& lb,
             const Eigen::Ref<const Eigen::VectorXd>& ub, const DecisionVariables& vars, py::object jacobian,
             const std::string& name) {
            return self.AddConstraint(MakePythonFunction(name, vars.size(), static_cast<int>(lb.size()),
                                                         std::move(function), std::move(jacobian)),
                                      lb, ub, vars);
          },
          py::arg("function"), py::arg("lb"), py::arg("ub"), py::arg("vars"), py::arg("jacobian") = py::none(),
          py::arg("name") = "python_constraint",
          "Adds lb <= function(x) <= ub (function returns an array of len(lb)), with jacobian(x) -> dense array or "
          "finite differences.")
      .def(
          "AddLinearConstraint",
          [](MathematicalProgram& self, const Eigen::Ref<const Eigen::MatrixXd>& A,
             const Eigen::Ref<const Eigen::VectorXd>& lb, const Eigen::Ref<const Eigen::VectorXd>& ub,
             const DecisionVariables& vars) { return Binding<Constraint>(self.AddLinearConstraint(ToSparse(A), lb, ub, vars)); },
          py::arg("A"), py::arg("lb"), py::arg("ub"), py::arg("vars"), "Adds lb <= A x <= ub (A dense).")
      .def(
          "AddLinearEqualityConstraint",
          [](MathematicalProgram& self, const Eigen::Ref<const Eigen::MatrixXd>& A,
             const Eigen::Ref<const Eigen::VectorXd>& b, const DecisionVariables& vars) {
            return Binding<Constraint>(self.AddLinearEqualityConstraint(ToSparse(A), b, vars));
          },
          py::arg("A"), py::arg("b"), py::arg("vars"), "Adds A x = b (A dense).")
      .def(
          "AddBoundingBoxConstraint",
          [](MathematicalProgram& self, const Eigen::Ref<const Eigen::VectorXd>& lb,
             const Eigen::Ref<const Eigen::VectorXd>& ub, const DecisionVariables& vars) {
            return Binding<Constraint>(self.AddBoundingBoxConstraint(lb, ub, vars));
          },
          py::arg("lb"), py::arg("ub"), py::arg("vars"), "Adds lb <= x <= ub on `vars`.")
      .def(
          "AddBoundingBoxConstraint",
          [](MathematicalProgram& self, double lb, double ub, const DecisionVariables& vars) {
            return Binding<Constraint>(self.AddBoundingBoxConstraint(lb, ub, vars));
          },
          py::arg("lb"), py::arg("ub"), py::arg("vars"), "Adds lb <= x_i <= ub for every variable of `vars`.")
      .def("costs", &MathematicalProgram::costs, "Scalar costs, in insertion order.")
      .def("least_squares_costs", &MathematicalProgram::least_squares_costs, "Least-squares residuals.")
      .def("constraints", &MathematicalProgram::constraints, "Constraints other than bounding boxes.")
      .def(
          "bounding_box_constraints",
          [](const MathematicalProgram& self) {
            std::vector<Binding<Constraint>> out(self.bounding_box_constraints().begin(),
                                                 self.bounding_box_constraints().end());
            return out;
          },
          "Bounding boxes, in insertion order.")
      .def("variable_lower_bounds", &MathematicalProgram::variable_lower_bounds,
           "Per-variable lower bounds (intersection of the bounding boxes).")
      .def("variable_upper_bounds", &MathematicalProgram::variable_upper_bounds,
           "Per-variable upper bounds (intersection of the bounding boxes).")
      .def("EvalCost", &MathematicalProgram::EvalCost, py::arg("x"), "The objective at x.")
      .def("id", &MathematicalProgram::id, "Identifier carried by the program's DecisionVariables.");

  py::class_<SolverOptions>(m, "SolverOptions",
                            "Options keyed by solver (\"ipopt\", \"nlopt\", \"least_squares\") and option name; "
                            "unknown keys and names are errors when solving.")
      .def(py::init<>(), "No options.")
      .def("Set", py::overload_cast<const std::string&, const std::string&, int>(&SolverOptions::Set),
           py::arg("solver"), py::arg("option"), py::arg("value"), "Sets an integer option.")
      .def("Set", py::overload_cast<const std::string&, const std::string&, double>(&SolverOptions::Set),
           py::arg("solver"), py::arg("option"), py::arg("value"), "Sets a numeric option.")
      .def("Set", py::overload_cast<const std::string&, const std::string&, const std::string&>(&SolverOptions::Set),
           py::arg("solver"), py::arg("option"), py::arg("value"), "Sets a string option.")
      .def("Get", &SolverOptions::Get, py::arg("solver"), "The options of `solver` as a dict.")
      .def("solver_keys", &SolverOptions::solver_keys, "Solver keys with at least one option, sorted.");

  py::enum_<SolutionStatus>(m, "SolutionStatus", "How a solve ended.")
      .value("kSolved", SolutionStatus::kSolved, "Converged to a (locally) optimal, feasible point.")
      .value("kInfeasible", SolutionStatus::kInfeasible, "Stopped at a point that violates the constraints.")
      .value("kUnbounded", SolutionStatus::kUnbounded, "The objective decreased without bound.")
      .value("kIterationLimit", SolutionStatus::kIterationLimit, "Hit the iteration or evaluation limit.")
      .value("kTimeLimit", SolutionStatus::kTimeLimit, "Hit the time limit.")
      .value("kNumericalFailure", SolutionStatus::kNumericalFailure, "The solver could not make progress.")
      .value("kFailed", SolutionStatus::kFailed, "Any other failure; see SolverResult.message.");
  m.def("to_string", py::overload_cast<SolutionStatus>(&to_string), py::arg("status"),
        "\"solved\", \"infeasible\", \"iteration limit\", ...");

  py::class_<SolverResult>(m, "SolverResult", "Everything a solver reports about one solve (picklable).")
      .def(py::init<>(), "An empty result.")
      .def_readonly("solver_name", &SolverResult::solver_name, "The solver's name, e.g. \"ipopt\".")
      .def_readonly("status", &SolverResult::status, "How the solve ended.")
      .def_readonly("x", &SolverResult::x, "Final decision vector.")
      .def_readonly("objective", &SolverResult::objective, "Objective at x.")
      .def_readonly("constraint_violation", &SolverResult::constraint_violation,
                    "Largest violation of constraints and bounds at x.")
      .def_readonly("constraint_duals", &SolverResult::constraint_duals,
                    "Multipliers of the stacked constraint rows (L = f + lambda' g); empty if none.")
      .def_readonly("bound_duals", &SolverResult::bound_duals, "Bound multipliers z_upper - z_lower; empty if none.")
      .def_readonly("iterations", &SolverResult::iterations, "Iterations (Ipopt, least squares) or -1.")
      .def_readonly("evaluations", &SolverResult::evaluations, "Objective evaluations (NLopt) or -1.")
      .def_readonly("wall_time_seconds", &SolverResult::wall_time_seconds, "Wall time of the whole solve.")
      .def_readonly("message", &SolverResult::message, "The solver's own account of the ending.")
      .def("is_success", &SolverResult::is_success, "True if status is kSolved.")
      .def(py::pickle(&ResultState, &ResultFromState), "Pickles every field.")
      .def("__repr__", [](const SolverResult& r) {
        return "<SolverResult " + r.solver_name + ": " + to_string(r.status) + ", objective " +
               cairn::FormatShort(r.objective) + ">";
      }, "<SolverResult solver: status, objective ...>.");

  py::class_<Solver>(m, "Solver",
                     "A swappable solver for MathematicalProgram; create one by type or by name (MakeSolver). "
                     "Solve() releases the GIL.")
      .def("name", &Solver::name, "The name MakeSolver accepts, e.g. \"ipopt\".")
      .def("options_key", &Solver::options_key, "The SolverOptions key it reads.")
      .def("available", &Solver::available, "True if the solver's library is present.")
      .def("CheckSupport", &Solver::CheckSupport, py::arg("prog"),
           "\"\" if the solver can handle `prog`, else one sentence why not.")
      .def("Solve", &SolveWith, py::arg("prog"), py::arg("initial_guess") = py::none(), py::arg("options") = py::none(),
           "Solves from `initial_guess` (default: the program's) with `options`; ValueError for an unsupported "
           "program, a bad guess or unknown options. Exceptions raised by Python costs reach the caller.");
  py::class_<IpoptSolver, Solver>(m, "IpoptSolver", "Ipopt (interior point, sparse); solves run one at a time.")
      .def(py::init<>(), "Name \"ipopt\".");
  py::class_<NloptSolver, Solver>(m, "NloptSolver", "NLopt algorithms, alone or as '+'-joined stages.")
      .def(py::init<const std::string&>(), py::arg("algorithms"), "E.g. \"SLSQP\" or \"ORIG_DIRECT+SLSQP\".")
      .def("stages", &NloptSolver::stages, "NLopt's names of the stages.")
      .def_static("AlgorithmNames", &NloptSolver::AlgorithmNames, "Every NLopt algorithm name.");
  py::class_<LeastSquaresSolver, Solver>(m, "LeastSquaresSolver",
                                         "Levenberg-Marquardt / Gauss-Newton on CHOLMOD for least-squares programs.")
      .def(py::init<>(), "Name \"least_squares\".");

  m.def("MakeSolver", &MakeSolver, py::arg("name"),
        "A solver by name: \"ipopt\", \"least_squares\" or \"nlopt:<stages>\"; ValueError listing valid names.");
  m.def("SolverNameExamples", &SolverNameExamples, "Example names MakeSolver accepts.");
  m.def("ChooseSolver", &ChooseSolver, py::arg("prog"),
        "The solver Solve(prog) would use: least squares for least-squares programs, else Ipopt.");
  m.def(
      "Solve",
      [](const MathematicalProgram& prog, const std::optional<SolverOptions>& options) {
        const SolverOptions opts = options ? *options : SolverOptions();
        py::gil_scoped_release release;
        return Solve(prog, opts);
      },
      py::arg("prog"), py::arg("options") = py::none(),
      "Solves `prog` from its initial guess with ChooseSolver(prog), without the GIL.");

  py::class_<GradientCheckResult> check(m, "GradientCheckResult",
                                        "How well every Jacobian (and Hessian) agrees with finite differences.");
  py::class_<GradientCheckResult::Entry>(check, "Entry", "One compared derivative entry.")
      .def_readonly("term", &GradientCheckResult::Entry::term, "Binding label.")
      .def_readonly("kind", &GradientCheckResult::Entry::kind, "\"cost\", \"constraint\", ...")
      .def_readonly("output", &GradientCheckResult::Entry::output, "Output row of the evaluator.")
      .def_readonly("variable", &GradientCheckResult::Entry::variable, "Program variable of the column.")
      .def_readonly("analytic", &GradientCheckResult::Entry::analytic, "The evaluator's value.")
      .def_readonly("finite_difference", &GradientCheckResult::Entry::finite_difference, "Finite-difference value.")
      .def_readonly("error", &GradientCheckResult::Entry::error, "Relative error.")
      .def_readonly("in_pattern", &GradientCheckResult::Entry::in_pattern, "False if missing from the pattern.");
  check.def_readonly("passed", &GradientCheckResult::passed, "True if every error is within the tolerance.")
      .def_readonly("max_error", &GradientCheckResult::max_error, "The largest error.")
      .def_readonly("num_checked", &GradientCheckResult::num_checked, "Entries compared.")
      .def_readonly("num_failed", &GradientCheckResult::num_failed, "Entries above the tolerance.")
      .def_readonly("tolerance", &GradientCheckResult::tolerance, "The tolerance used.")
      .def_readonly("worst_entries", &GradientCheckResult::worst_entries, "The worst entries, largest error first.")
      .def("ToString", &GradientCheckResult::ToString, "A readable report.");
  m.def("CheckGradients",
        py::overload_cast<const MathematicalProgram&, const Eigen::Ref<const Eigen::VectorXd>&, double, int>(
            &CheckGradients),
        py::arg("prog"), py::arg("x"), py::arg("tolerance") = 1e-5, py::arg("max_reported") = 10,
        "Compares every Jacobian of `prog`'s terms at x with central finite differences.");
  m.def("CheckGradients",
        py::overload_cast<const Evaluator&, const Eigen::Ref<const Eigen::VectorXd>&, double, int>(&CheckGradients),
        py::arg("evaluator"), py::arg("x"), py::arg("tolerance") = 1e-5, py::arg("max_reported") = 10,
        "The same check for one evaluator.");
}

}  // namespace cairn::python
