"""cairn.perception on numpy images: cost volumes, confidence, WTA, occupancy, friction, segmenters and systems."""

import os
import pickle

import numpy as np
import pytest

import cairn.perception as perception
from cairn.systems import AbstractValue, DiagramBuilder, LeafSystem
from conftest import SHARED_DIR, source_path

MIDDLEBURY = os.path.join(SHARED_DIR, "data", "middlebury")


def shifted_pair(height=40, width=80, disparity=6, seed=0):
    """A textured left image and the right image it sees shifted by `disparity` pixels."""
    rng = np.random.default_rng(seed)
    wide = rng.integers(0, 256, size=(height, width + disparity), dtype=np.uint8)
    left = np.ascontiguousarray(wide[:, :width])  # left pixel x sees what the right one sees at x - disparity
    right = np.ascontiguousarray(wide[:, disparity:])
    return left, right


def options(max_disparity=15, window=5):
    o = perception.CostVolumeOptions()
    o.max_disparity = max_disparity
    o.window = window
    o.num_threads = 1
    return o


def test_cost_volume_and_winner_take_all_find_the_shift():
    left, right = shifted_pair()
    costs = perception.ComputeCostVolume(left, right, options())
    assert (costs.height(), costs.width(), costs.num_disparities()) == (40, 80, 16)
    values = costs.array()
    assert values.shape == (40, 80, 16) and values.dtype == np.float32
    assert np.isinf(values[10, 0, 5])  # x - d leaves the right image
    wta = perception.ComputeWinnerTakeAll(costs)
    interior = wta.best_index[5:-5, 20:-5]
    assert np.all(interior == 6)
    assert wta.lr_consistent.dtype == np.uint8
    fused_costs, fused_wta = perception.ComputeCostVolumeAndWinnerTakeAll(left, right, options())
    np.testing.assert_array_equal(fused_costs.array(), values)
    np.testing.assert_array_equal(fused_wta.disparity, wta.disparity)


def test_confidence_sums_to_one():
    left, right = shifted_pair()
    costs = perception.ComputeCostVolume(left, right, options())
    wta = perception.ComputeWinnerTakeAll(costs)
    samples = perception.CollectConsistentWtaCosts(costs, wta)
    assert samples.dtype == np.float32 and samples.size > 1000
    model = perception.ConfidenceModel.FitMaximumLikelihood(perception.ConfidenceModelType.kMerrell,
                                                            perception.CostFunction.kBtSad, list(samples))
    assert model.parameter() > 0 and "merrell" in model.Describe()
    confidence = perception.ComputeConfidence(costs, model, 1).array()
    np.testing.assert_allclose(confidence[:, 20:, :].sum(axis=2), 1.0, atol=1e-4)
    assert np.all(confidence[10:30, 30:70].argmax(axis=2) == 6)


def test_image_type_errors():
    left, right = shifted_pair()
    with pytest.raises(ValueError, match="float16"):
        perception.ComputeCostVolume(left.astype(np.float16), right, options())
    with pytest.raises(ValueError, match="4 dimensions"):
        perception.ComputeCostVolume(left[None, :, :, None], right, options())
    with pytest.raises(ValueError, match="8-bit grey"):
        perception.ComputeCostVolume(left.astype(np.float32), right.astype(np.float32), options())
    with pytest.raises(ValueError, match="window"):
        perception.ComputeCostVolume(left, right, options(window=4))


def test_occupancy_grid_from_a_synthetic_plane():
    calibration = perception.StereoCalibration(100.0, 100.0, 39.5, 29.5, 0.1)
    scene = perception.SyntheticStereoScene()
    texture = perception.ProceduralTexture()
    texture.scale = 0.02
    scene.AddPlane(np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -1.0]), texture, 1)  # 1 m in front
    renderer = perception.SyntheticStereoRenderer(calibration, 80, 60)
    frame = renderer.Render(scene, np.eye(4))
    assert frame.left.shape == (60, 80) and frame.left.dtype == np.uint8
    np.testing.assert_allclose(frame.depth[30, 40], 1.0, atol=1e-9)
    o = options(max_disparity=20)
    o.min_disparity = 1
    costs = perception.ComputeCostVolume(frame.left, frame.right, o)
    model = perception.ConfidenceModel.Merrell(perception.CostFunction.kBtSad, 2000.0)
    confidence = perception.ComputeConfidence(costs, model, 1)
    grid = perception.OccupancyGrid(np.array([-0.5, -0.4, 0.5]), 0.05, np.array([20, 16, 20]))
    sensor = perception.CostCurveSensorModel()
    sensor.Integrate(confidence, calibration, np.eye(4), grid)
    occupied = grid.OccupiedPoints(0.6)
    assert len(occupied) > 20
    ply = grid.PlyText(0.6)
    assert ply.startswith("ply\n") and "element vertex %d\n" % len(occupied) in ply
    assert len(ply.strip().split("\n")) == 8 + len(occupied)  # 8 header lines, one line per cell
    assert np.median(occupied[:, 2]) == pytest.approx(1.0, abs=0.05)
    assert grid.probabilities().shape == (20, 16, 20)
    copy = pickle.loads(pickle.dumps(grid))
    np.testing.assert_array_equal(copy.log_odds_array(), grid.log_odds_array())
    with pytest.raises(IndexError):
        grid.log_odds(grid.num_cells())
    truth = perception.RasterizeScene(scene, grid)
    score = perception.ScoreOccupancy(grid, truth, 0.6)
    assert score.precision > 0.5


def test_friction_quantile_image_matches_per_pixel_quantiles():
    registry = perception.MaterialRegistry.ThesisTable33()
    rng = np.random.default_rng(4)
    probabilities = rng.random((6, 7, registry.size())).astype(np.float32)
    probabilities /= probabilities.sum(axis=2, keepdims=True)
    image = perception.FrictionQuantileImage(registry)
    quantiles = image.Compute(probabilities)
    assert quantiles.shape == (6, 7) and quantiles.dtype == np.float32
    for y, x in [(0, 0), (3, 4), (5, 6)]:
        exact = perception.FrictionQuantile(registry, probabilities[y, x].astype(np.float64), 0.95,
                                            perception.QuantileMethod.kExact)
        assert quantiles[y, x] == pytest.approx(exact, abs=2e-3)
    bad = probabilities.copy()
    bad[2, 3, 0] += 0.5
    with pytest.raises(ValueError, match="sum|pixel"):
        image.Compute(bad)
    copy = pickle.loads(pickle.dumps(registry))
    assert copy.labels() == registry.labels()


def test_builtin_segmenter_on_numpy_images():
    segmenter = perception.MakeMaterialSegmenter("builtin:" + source_path("data", "models",
                                                                        "builtin_material_segmenter.yaml"))
    rng = np.random.default_rng(5)
    image = rng.integers(0, 256, size=(48, 64, 3), dtype=np.uint8)
    probabilities = segmenter.Segment(image)
    assert probabilities.shape == (48, 64, segmenter.num_labels())
    np.testing.assert_allclose(probabilities.sum(axis=2), 1.0, atol=1e-4)
    registry = perception.MaterialRegistry.ThesisTable33()
    estimator = perception.FrictionEstimator(registry, segmenter)
    context = estimator.CreateDefaultContext()
    estimator.GetInputPort("image").FixValue(context, image)
    quantiles = estimator.GetOutputPort("friction_quantile").Eval(context)
    assert quantiles.shape == (48, 64) and np.all(quantiles >= 0.0)


class ImageSource(LeafSystem):
    """Outputs a fixed image on an abstract port of C++ type cv::Mat, so that C++ image inputs accept it."""

    def __init__(self, image):
        super().__init__()
        self.image = image
        self.DeclareAbstractOutputPort("image", AbstractValue.Make(image, type="Image"), lambda c, out: self.image)


class VolumeSink(LeafSystem):
    """Reads a DisparityVolume from a C++ output."""

    def __init__(self):
        super().__init__()
        self.volume = self.DeclareAbstractInputPort("confidence", perception.DisparityVolume())
        self.DeclareVectorOutputPort("best", 1, self.CalcBest)

    def CalcBest(self, context, best):
        volume = self.volume.Eval(context, copy=False)
        best[0] = np.argmax(volume.array()[20, 40])


def test_stereo_matcher_between_python_systems():
    left, right = shifted_pair()
    matcher_options = perception.StereoMatcher.Options()
    matcher_options.cost_volume = options()
    builder = DiagramBuilder()
    left_source = builder.AddSystem(ImageSource(left))
    right_source = builder.AddSystem(ImageSource(right))
    matcher = builder.AddSystem(perception.StereoMatcher(matcher_options))
    sink = builder.AddSystem(VolumeSink())
    builder.Connect(left_source.get_output_port(0), matcher.get_left_input_port())
    builder.Connect(right_source.get_output_port(0), matcher.get_right_input_port())
    builder.Connect(matcher.get_confidence_output_port(), sink.get_input_port(0))
    diagram = builder.Build()
    context = diagram.CreateDefaultContext()
    assert sink.get_output_port(0).Eval(diagram.GetSubsystemContext(sink, context))[0] == 6
    wta = matcher.get_wta_output_port().Eval(diagram.GetSubsystemContext(matcher, context))
    assert isinstance(wta, perception.WtaResult)
    assert np.all(wta.best_index[5:-5, 20:-5] == 6)


def test_image_port_refuses_other_values():
    matcher = perception.StereoMatcher(perception.StereoMatcher.Options())
    context = matcher.CreateDefaultContext()
    with pytest.raises(TypeError, match="Image"):
        matcher.get_left_input_port().FixValue(context, "not an image")
    builder = DiagramBuilder()
    source = builder.AddSystem(perception.StereoMatcher(perception.StereoMatcher.Options()))
    sink = builder.AddSystem(VolumeSink())
    with pytest.raises(RuntimeError, match="WtaResult.*DisparityVolume.*different types"):
        builder.Connect(source.get_wta_output_port(), sink.get_input_port(0))


@pytest.mark.skipif(not os.path.isdir(os.path.join(MIDDLEBURY, "tsukuba")), reason="no Middlebury data")
def test_middlebury_tsukuba():
    pair = perception.MiddleburyPair.Load(os.path.join(MIDDLEBURY, "tsukuba"), 16)
    o = perception.CostVolumeOptions()
    o.max_disparity = 15
    costs, wta = perception.ComputeCostVolumeAndWinnerTakeAll(pair.left, pair.right, o, perception.WtaOptions())
    samples = perception.CollectConsistentWtaCosts(costs, wta)
    model = perception.ConfidenceModel.FitMaximumLikelihood(perception.ConfidenceModelType.kMerrell,
                                                            o.cost, list(samples))
    confidence = perception.ComputeConfidence(costs, model)
    evaluation = perception.EvaluateStereo(confidence, wta, pair.gt_left)
    assert 0.0 < evaluation.bad_pixel_rate < 0.3
    assert evaluation.auc_optimal <= evaluation.auc < evaluation.bad_pixel_rate


def test_synthetic_stereo_to_occupancy_diagram():
    """SyntheticStereoSource -> StereoMatcher -> ConfidenceToOccupancy, simulated: images, volumes, poses (4x4) and
    grids cross C++ ports, and the grid comes out in Python."""
    calibration = perception.StereoCalibration(100.0, 100.0, 39.5, 29.5, 0.1)
    scene = perception.SyntheticStereoScene()
    scene.AddPlane(np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -1.0]), perception.ProceduralTexture(), 1)
    renderer = perception.SyntheticStereoRenderer(calibration, 80, 60)
    shifted = np.eye(4)
    shifted[0, 3] = 0.05
    matcher_options = perception.StereoMatcher.Options()
    matcher_options.cost_volume = options(max_disparity=20)
    matcher_options.cost_volume.min_disparity = 1
    matcher_options.parameter = 2000.0
    grid = perception.OccupancyGrid(np.array([-0.5, -0.4, 0.5]), 0.05, np.array([20, 16, 20]))
    builder = DiagramBuilder()
    source = builder.AddSystem(perception.SyntheticStereoSource(scene, renderer, [np.eye(4), shifted], 0.1))
    matcher = builder.AddSystem(perception.StereoMatcher(matcher_options))
    fusion = builder.AddSystem(perception.ConfidenceToOccupancy(grid, calibration, 0.1))
    builder.Connect(source.get_left_output_port(), matcher.get_left_input_port())
    builder.Connect(source.get_right_output_port(), matcher.get_right_input_port())
    builder.Connect(matcher.get_confidence_output_port(), fusion.get_confidence_input_port())
    builder.Connect(source.get_pose_output_port(), fusion.get_pose_input_port())
    builder.ExportOutput(fusion.get_grid_output_port(), "grid")
    builder.ExportOutput(source.get_pose_output_port(), "X_WC")
    diagram = builder.Build()
    from cairn.systems import Simulator

    simulator = Simulator(diagram)
    simulator.AdvanceTo(0.15)
    context = simulator.get_context()
    np.testing.assert_array_equal(diagram.GetOutputPort("X_WC").Eval(context), shifted)
    fused = diagram.GetOutputPort("grid").Eval(context)
    assert isinstance(fused, perception.OccupancyGrid)
    occupied = fused.OccupiedPoints(0.6)
    assert len(occupied) > 20 and np.median(occupied[:, 2]) == pytest.approx(1.0, abs=0.05)


def test_stereo_source_reads_a_sequence(tmp_path):
    import matplotlib.image

    left, right = shifted_pair()
    matplotlib.image.imsave(tmp_path / "l.png", left, cmap="gray", vmin=0, vmax=255)
    matplotlib.image.imsave(tmp_path / "r.png", right, cmap="gray", vmin=0, vmax=255)
    (tmp_path / "seq.yaml").write_text(
        "calibration: {fx: 100, fy: 100, cx: 40, cy: 20, baseline: 0.1}\n"
        "frames:\n  - {left: l.png, right: r.png, translation: [1, 2, 3], rotation_wxyz: [1, 0, 0, 0]}\n")
    source = perception.StereoSource(str(tmp_path / "seq.yaml"), 0.5)
    context = source.CreateDefaultContext()
    image = source.get_left_output_port().Eval(context)
    assert image.dtype == np.uint8 and image.shape == left.shape
    # matplotlib writes grey through a colour map, OpenCV reads it back as luma: within one level.
    assert np.abs(image.astype(int) - left).max() <= 1
    np.testing.assert_array_equal(source.get_pose_output_port().Eval(context)[:3, 3], [1.0, 2.0, 3.0])
    assert source.calibration().fx == 100.0
    with pytest.raises(ValueError, match="missing.yaml"):
        perception.StereoSource(str(tmp_path / "missing.yaml"), 0.5)


def test_disparity_to_depth_between_the_matcher_and_a_consumer():
    """DisparityToDepth turns the matcher's WTA into depth fx * b / d; the forced occupancy update and its offset."""
    left, right = shifted_pair(disparity=5)
    calibration = perception.StereoCalibration(50.0, 50.0, 39.5, 19.5, 0.1)
    matcher_options = perception.StereoMatcher.Options()
    matcher_options.cost_volume = options()
    builder = DiagramBuilder()
    left_source = builder.AddSystem(ImageSource(left))
    right_source = builder.AddSystem(ImageSource(right))
    matcher = builder.AddSystem(perception.StereoMatcher(matcher_options))
    to_depth = builder.AddSystem(perception.DisparityToDepth(calibration))
    builder.Connect(left_source.get_output_port(0), matcher.get_left_input_port())
    builder.Connect(right_source.get_output_port(0), matcher.get_right_input_port())
    builder.Connect(matcher.get_wta_output_port(), to_depth.get_wta_input_port())
    builder.ExportOutput(to_depth.get_depth_output_port(), "depth")
    builder.ExportOutput(matcher.get_wta_output_port(), "wta")
    diagram = builder.Build()
    context = diagram.CreateDefaultContext()
    depth = diagram.GetOutputPort("depth").Eval(context)
    disparity = np.array(diagram.GetOutputPort("wta").Eval(context).disparity)  # sub-pixel, about 5
    assert depth.dtype == np.float32 and depth.shape == left.shape
    inner = (slice(5, -5), slice(20, -5))
    np.testing.assert_allclose(depth[inner], 50.0 * 0.1 / disparity[inner], rtol=1e-5)
    np.testing.assert_allclose(depth[inner], 1.0, rtol=0.1)
    with pytest.raises(ValueError, match="min_peak_ratio must be a finite number >= 1"):
        bad = perception.DisparityToDepth.Options()
        bad.min_peak_ratio = 0.5
        perception.DisparityToDepth(calibration, bad)
    fusion = perception.ConfidenceToOccupancy(
        perception.OccupancyGrid(np.zeros(3), 0.1, np.array([2, 2, 2])), calibration, 0.1, offset=0.1)
    assert fusion.offset() == 0.1
    with pytest.raises(ValueError, match="offset -1 s"):
        perception.ConfidenceToOccupancy(
            perception.OccupancyGrid(np.zeros(3), 0.1, np.array([2, 2, 2])), calibration, 0.1, offset=-1.0)


def test_contact_friction_learner_credits_slips_to_the_material_under_the_foot():
    """Wet tiles: the segmenter says ceramic, the feet slip at 0.3; ceramic's belief drops, wood's does not move."""
    registry = perception.MaterialRegistry.ThesisTable33()
    xs, ys = np.meshgrid(np.arange(0.01, 2.0, 0.02), np.arange(-0.49, 0.5, 0.02))
    points = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], axis=1)
    weights = np.zeros((len(points), registry.size()), dtype=np.float32)
    weights[points[:, 0] < 1.0, registry.IndexOf("ceramic")] = 1.0
    weights[points[:, 0] >= 1.0, registry.IndexOf("wood")] = 1.0
    cloud = perception.FrictionPointCloud(points, np.zeros(len(points), dtype=np.float32), weights)
    learner = perception.ContactFrictionLearner(registry, 0.1)
    context = learner.CreateDefaultContext()
    learner.GetInputPort("friction_points").FixValue(context, cloud)
    slips = [perception.FootContact(np.array([x, 0.0, 0.0]), perception.ContactObservation.Slipped(0.3))
             for x in (0.3, 0.5, 0.7)]
    learner.GetInputPort("contacts").FixValue(context, slips + [
        perception.FootContact(np.array([5.0, 0.0, 0.0]), perception.ContactObservation.Slipped(0.3))])
    learner.ExecuteForcedEvents(context)
    state = learner.learning(context)
    assert (state.seen, state.learned, state.skipped) == (4, 3, 1)
    learned = learner.GetOutputPort("registry").Eval(context)
    ceramic, wood = registry.IndexOf("ceramic"), registry.IndexOf("wood")
    assert learned.material(ceramic).friction.Mean() < 0.3 < registry.material(ceramic).friction.Mean()
    assert learned.material(wood).friction.Mean() == registry.material(wood).friction.Mean()
    mixture = learner.MixtureUnder(cloud, np.array([1.5, 0.0, 0.0]))
    assert mixture[wood] == pytest.approx(1.0)
    assert learner.MixtureUnder(cloud, np.array([5.0, 0.0, 0.0])) is None
    with pytest.raises(ValueError, match="period 0 s must be positive"):
        perception.ContactFrictionLearner(registry, 0.0)
