"""cairn.planning, the main diagram: the scenario as the head camera sees it, the perception in front of the walk,
and one run from the camera to the plant on thesis 5.2.3's mock-up."""

import math

import numpy as np
import pytest

import cairn.multibody as mb
import cairn.perception as perception
import cairn.planning as planning
from conftest import source_path

HUMANOID = source_path("data", "robots", "cairn_humanoid.urdf")
CONTROL = source_path("data", "robots", "cairn_humanoid_control.yaml")
SEGMENTER = "builtin:" + source_path("data", "models", "builtin_material_segmenter.yaml")


def mockup(name="mockup.yaml"):
    return planning.FootstepScenario.Load(source_path("examples", "scenarios", "mockup", name))


def test_the_head_camera_looks_down_along_the_heading():
    head = planning.HeadCamera()
    head.height, head.pitch_deg = 1.2, 60.0
    X_WC = planning.ScenarioCameraPose(mockup().start(), head)
    np.testing.assert_allclose(X_WC[:3, 3], [0.0, 0.0, 1.2], atol=1e-12)
    np.testing.assert_allclose(X_WC[:3, 2], [math.cos(math.pi / 3), 0.0, -math.sin(math.pi / 3)], atol=1e-12)
    head.pitch_deg = 100.0
    with pytest.raises(ValueError, match=r"pitch_deg must be in \(0, 90\]"):
        planning.ScenarioCameraPose(mockup().start(), head)


def test_the_perception_setup_maps_the_scenario():
    camera = planning.SyntheticCamera()
    setup = planning.PerceptionSetupFromScenario(mockup(), camera.Calibration(),
                                                 perception.MakeMaterialSegmenter(SEGMENTER))
    assert setup.grid.resolution() == pytest.approx(0.025)
    np.testing.assert_allclose(setup.grid.min_corner(), [-0.6, -0.9, -0.1], atol=1e-12)
    assert setup.segmenter is not None and setup.eta == pytest.approx(0.95)
    with pytest.raises(ValueError, match="max_depth must be in"):
        planning.PerceptionSetupFromScenario(mockup(), camera.Calibration(),
                                             perception.MakeMaterialSegmenter(SEGMENTER), 0.1)


def test_the_main_diagram_perceives_then_plans_on_what_it_saw(oracle, walking_model):
    scenario = mockup()
    options = mb.UrdfOptions()
    options.floating_base = True
    robot = mb.ParseUrdfFile(HUMANOID, options)
    controller = mb.JointPdController.Load(robot, CONTROL)
    walk = planning.WalkSetupFromScenario(scenario, oracle, walking_model,
                                          planning.WalkingObjective.kComWorkPlusHeat, robot, controller)
    walk.planner.search.time_limit = 600.0
    walk.planner.search.max_expansions = 20000
    camera = planning.SyntheticCamera()
    setup = planning.PerceptionSetupFromScenario(scenario, camera.Calibration(),
                                                 perception.MakeMaterialSegmenter(SEGMENTER))
    source = planning.ScenarioCamera(scenario, camera, setup.period)
    main = planning.BuildMainDiagram(walk, setup, source)
    names = {s.get_name() for s in main.diagram.GetSystems()}
    assert {"camera", "stereo", "depth", "occupancy", "friction", "terrain_assembler", "footsteps", "plant"} <= names
    assert source.get_name() == "camera"  # the Python object now views the diagram's block
    run = planning.WalkRunOptions()
    run.settle_time = 0.2
    record = planning.RunMainDiagram(main, run)
    terrain = record.terrain
    assert terrain is not None and (terrain.cols(), terrain.rows()) == (96, 72)
    # What the first frame's perception made, as the plan was made on it.
    assert record.image.shape == (240, 320, 3) and record.image.dtype == np.uint8
    assert record.material_probabilities.shape == (240, 320, setup.registry.size())
    np.testing.assert_allclose(record.material_probabilities.sum(axis=2), 1.0, atol=1e-3)
    assert record.friction_quantile.shape == (240, 320)
    assert record.grid is not None and tuple(record.grid.dims()) == (96, 72, 44)
    # The planner read the perceived terrain: the wood ahead at its friction quantile (materials.yaml: N(0.3, 0.12),
    # Q_0.05 = 0.103), the points of a cell fused as independent looks at its material.
    frictions = [terrain.friction(*terrain.CellAt(x, 0.3)) for x in np.arange(0.3, 1.1, 0.05)]
    assert float(np.median(frictions)) == pytest.approx(0.3 - 1.6449 * 0.12, abs=0.005)
    # The plan made on it is walked to the goal without a fall (docs/main_diagram.md).
    assert record.walk.start.ready, record.walk.start.reason
    assert len(record.walk.plan.steps) >= 4
    assert not record.walk.fell, record.walk.fall_reason
    assert record.walk.samples[-1].com[0] > 0.8
