"""numpy without copies where layouts agree (same buffer address), and correct copies where they do not."""

import gc

import numpy as np

import cairn.multibody as mb
import cairn.optimization as opt
import cairn.perception as perception
from cairn.systems import LeafSystem
from conftest import source_path


def address(array):
    return array.__array_interface__["data"][0]


def test_eigen_input_is_not_copied_when_contiguous():
    seen = []

    def value(x):
        seen.append((address(x), np.array(x)))
        return [x.sum()]

    evaluator = opt.FunctionEvaluator("sum", 4, 1, value)
    x = np.arange(4.0)
    assert evaluator.Eval(x)[0] == 6.0
    assert seen[-1][0] == address(x)  # the callback sees the caller's buffer
    strided = np.arange(8.0)[::2]  # not contiguous: Eigen::Ref copies it
    assert evaluator.Eval(strided)[0] == 12.0
    assert seen[-1][0] != address(strided)
    np.testing.assert_array_equal(seen[-1][1], [0.0, 2.0, 4.0, 6.0])


def test_row_major_matrices_are_copied_with_the_right_values():
    A = np.array([[1.0, 2.0, 0.0], [0.0, 3.0, 4.0]])  # C order; Eigen is column-major
    assert A.flags.c_contiguous and not A.flags.f_contiguous
    constraint = opt.LinearConstraint(A, np.zeros(2), np.ones(2))
    np.testing.assert_array_equal(constraint.A(), A)
    np.testing.assert_array_equal(constraint.Eval(np.array([1.0, 1.0, 1.0])), [3.0, 7.0])
    np.testing.assert_array_equal(opt.LinearConstraint(np.asfortranarray(A), np.zeros(2), np.ones(2)).A(), A)


def test_eigen_outputs_are_views_of_data_buffers():
    model = mb.ParseUrdfFile(source_path("data", "robots", "cairn_humanoid.urdf"))
    data = mb.Data(model)
    q = mb.NeutralConfiguration(model)
    tau = mb.GravityTorques(model, data, q)
    assert address(tau) == address(data.gravity_torques)
    assert tau.base is not None and not tau.flags.writeable
    before = tau.copy()
    mb.GravityTorques(model, data, mb.RandomConfiguration(model, 7))
    assert not np.array_equal(tau, before)  # a view: the next call on the same Data shows through


def test_images_are_written_in_place_and_read_without_copies():
    registry = perception.MaterialRegistry.ThesisTable33()
    rng = np.random.default_rng(1)
    probabilities = rng.random((5, 8, registry.size())).astype(np.float32)
    probabilities /= probabilities.sum(axis=2, keepdims=True)
    image = perception.FrictionQuantileImage(registry)
    out = np.full((5, 8), -1.0, dtype=np.float32)
    result = image.Compute(probabilities, out)
    assert result is out  # C++ wrote into the array's own memory through a cv::Mat header
    np.testing.assert_array_equal(out, image.Compute(probabilities))
    # Other layouts are copied first and give the same values.
    np.testing.assert_array_equal(image.Compute(np.asfortranarray(probabilities)), out)
    wide = np.concatenate([probabilities, probabilities], axis=1)[:, ::2]
    assert not wide.flags.c_contiguous
    np.testing.assert_array_equal(image.Compute(wide), image.Compute(np.ascontiguousarray(wide)))


def test_cv_mat_results_share_their_buffers():
    rng = np.random.default_rng(2)
    left = rng.integers(0, 256, size=(30, 50), dtype=np.uint8)
    right = np.roll(left, -3, axis=1)
    options = perception.CostVolumeOptions()
    options.max_disparity = 7
    options.window = 3
    costs = perception.ComputeCostVolume(left, right, options)
    view = costs.array()
    assert address(view) == address(costs.array())
    assert not view.flags.writeable
    del costs
    gc.collect()
    assert view.shape == (30, 50, 8) and np.isfinite(view[:, 10:]).all()  # the view keeps the volume alive
    wta = perception.ComputeWinnerTakeAll(perception.ComputeCostVolume(left, right, options))
    assert address(wta.disparity) == address(wta.disparity)
    disparity = wta.disparity
    del wta
    gc.collect()
    assert disparity.dtype == np.float32 and disparity.shape == (30, 50)


class Doubler(LeafSystem):
    def __init__(self):
        super().__init__()
        self.u = self.DeclareVectorInputPort("u", 3)
        self.DeclareVectorOutputPort("y", 3, self.Calc)
        self.output_addresses = []

    def Calc(self, context, y):
        self.output_addresses.append(address(y))
        y[:] = 2.0 * self.u.Eval(context)


def test_python_outputs_write_into_the_cache():
    system = Doubler()
    context = system.CreateDefaultContext()
    system.get_input_port(0).FixValue(context, [1.0, 2.0, 3.0])
    cached = system.get_output_port(0).Eval(context, copy=False)
    np.testing.assert_array_equal(cached, [2.0, 4.0, 6.0])
    assert system.output_addresses == [address(cached)]  # the callback's array is the cached vector itself
    copied = system.get_output_port(0).Eval(context)
    assert address(copied) != address(cached) and len(system.output_addresses) == 1  # cached: not recomputed
