"""cairn.planning's terrain from perception: AssembleTerrain, the TerrainAssembler system, occupied voxels in planning."""

import math

import numpy as np
import pytest

import cairn.perception as perception
import cairn.planning as planning


def floor_grid():
    """A 1 m x 0.5 m floor at z = 0 seen with probability 0.8, and a post whose top rises above 0.3 m."""
    grid = perception.OccupancyGrid(np.array([0.0, 0.0, -0.1]), 0.05, np.array([20, 10, 16]))
    for c in range(20):
        for r in range(10):
            grid.Update(grid.Index(np.array([c, r, 2])), math.log(0.8 / 0.2))
    for k in range(4, 14):
        grid.Update(grid.Index(np.array([5, 5, k])), math.log(0.7 / 0.3))
    return grid


def wood_points(registry):
    xs, ys = np.meshgrid(np.arange(0.005, 1.0, 0.01), np.arange(0.005, 0.5, 0.01))
    points = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], axis=1)
    # The post of floor_grid() hides the floor under it from a camera; no point confirms its cells either, so its
    # highest cell below 0.3 m is its ground.
    under_post = (points[:, 0] >= 0.25) & (points[:, 0] < 0.3) & (points[:, 1] >= 0.25) & (points[:, 1] < 0.3)
    points = points[~under_post]
    weights = np.zeros((len(points), registry.size()), dtype=np.float32)
    weights[:, registry.IndexOf("wood")] = 1.0
    return perception.FrictionPointCloud(points, np.zeros(len(points), dtype=np.float32), weights)


def test_assemble_terrain_and_the_system_agree():
    registry = perception.MaterialRegistry.ThesisTable33()
    grid, points = floor_grid(), wood_points(registry)
    terrain = planning.AssembleTerrain(grid, points, registry)
    assert (terrain.cols(), terrain.rows()) == (20, 10)
    assert terrain.height(3, 3) == pytest.approx(0.0, abs=1e-6)
    wood = np.zeros(registry.size())
    wood[registry.IndexOf("wood")] = 1.0
    expected = perception.FrictionQuantile(registry, wood, 0.95, perception.QuantileMethod.kExact)
    assert terrain.friction(3, 3) == pytest.approx(expected, abs=1e-4)
    centers, probabilities = terrain.occupied_voxels()
    assert centers.shape == (6, 3) and np.all(centers[:, 2] > 0.3)
    np.testing.assert_allclose(probabilities, 0.7, atol=1e-6)
    assert terrain.BoxFreeProbability(np.array([0.275, 0.275, 0.8]), np.array([0.15, 0.25, 0.35]), 0.0) == \
        pytest.approx(0.3 ** 3, rel=1e-5)

    assembler = planning.TerrainAssembler(registry)
    context = assembler.CreateDefaultContext()
    assembler.GetInputPort("grid").FixValue(context, grid)
    assembler.GetInputPort("friction_points").FixValue(context, points)
    out = assembler.GetOutputPort("terrain").Eval(context)
    assert out.friction(3, 3) == pytest.approx(terrain.friction(3, 3))

    options = planning.TerrainAssemblyOptions()
    options.eta = 1.5
    with pytest.raises(ValueError, match=r"eta is 1.5; it must be in \(0, 1\)"):
        planning.TerrainAssembler(registry, options)


def test_independent_fusion_outliers_and_gaps():
    """A segmenter sure of wood but for 6 % on paper: averaged, Q_0.05 is 0; fused as independent looks, the wood's.
    A cell a mismatch put 5 cm below the floor loses its ground; the hole it leaves is bridged."""
    registry = perception.MaterialRegistry.ThesisTable33()
    grid = floor_grid()
    points = wood_points(registry)
    xyz, weights = points.points_W.copy(), points.weights.copy()
    weights[:, registry.IndexOf("wood")] = 0.94
    weights[:, registry.IndexOf("paper")] = 0.06
    spike = (xyz[:, 0] >= 0.6) & (xyz[:, 0] < 0.65) & (xyz[:, 1] >= 0.15) & (xyz[:, 1] < 0.2)
    xyz[spike, 2] = -0.05
    points = perception.FrictionPointCloud(xyz, np.zeros(len(xyz), dtype=np.float32), weights)
    assert planning.AssembleTerrain(grid, points, registry).friction(3, 3) == 0.0
    options = planning.TerrainAssemblyOptions()
    options.fusion = planning.MaterialFusion.kIndependent
    wood = np.zeros(registry.size())
    wood[registry.IndexOf("wood")] = 1.0
    expected = perception.FrictionQuantile(registry, wood, 0.95, perception.QuantileMethod.kExact)
    terrain = planning.AssembleTerrain(grid, points, registry, options)
    assert terrain.friction(3, 3) == pytest.approx(expected, abs=1e-4)
    assert terrain.height(12, 3) == pytest.approx(-0.05, abs=1e-6)
    options.outlier_height, options.outlier_radius = 0.02, 0.1
    assert math.isnan(planning.AssembleTerrain(grid, points, registry, options).height(12, 3))
    options.median_heights = True
    assert planning.AssembleTerrain(grid, points, registry, options).height(11, 3) == pytest.approx(0.0, abs=1e-6)
    options.max_gap = 0.05
    bridged = planning.AssembleTerrain(grid, points, registry, options)
    assert bridged.height(12, 3) == pytest.approx(0.0, abs=1e-6)
    assert bridged.friction(12, 3) == pytest.approx(expected, abs=1e-4)
    options.max_gap = -1.0
    with pytest.raises(ValueError, match=r"max_gap is -1; it must be in \[0, 10\] m"):
        planning.TerrainAssembler(registry, options)


def test_voxels_and_the_planners_free_probability_level():
    terrain = planning.TerrainMap(np.array([0.0, 0.0]), 40, 40, 0.05)
    terrain.SetOccupiedVoxels(np.array([[1.0, 1.0, 0.8], [1.1, 1.2, 0.6]]), np.array([0.3, 0.5]), 0.05)
    assert terrain.voxel_size() == 0.05
    half = np.array([0.15, 0.25, 0.35])
    assert terrain.BoxFreeProbability(np.array([1.0, 1.0, 0.8]), half, 0.0) == pytest.approx(0.35)
    with pytest.raises(ValueError, match="2 centres but 1 probabilities"):
        terrain.SetOccupiedVoxels(np.zeros((2, 3)), np.array([0.5]), 0.05)
    with pytest.raises(ValueError, match="voxel 0"):
        terrain.SetOccupiedVoxels(np.zeros((1, 3)), np.array([1.5]), 0.05)
    options = planning.FootstepPlannerOptions()
    assert options.min_body_free_probability == pytest.approx(0.9)


def test_environment_from_terrain_weighs_voxels_by_probability():
    terrain = planning.TerrainMap(np.array([0.0, 0.0]), 10, 10, 0.05)
    terrain.AddObstacle(planning.TerrainMap.Obstacle("crate", np.array([0.2, 0.2, 0.1]), np.array([0.05, 0.05, 0.1])))
    terrain.SetOccupiedVoxels(np.array([[0.3, 0.3, 0.6]]), np.array([0.7]), 0.05)
    boxes = planning.EnvironmentFromTerrain(terrain)
    assert [b.name for b in boxes] == ["crate", "voxel 0"]
    assert boxes[0].probability == 1.0 and boxes[1].probability == pytest.approx(0.7)
    np.testing.assert_allclose(boxes[1].size, [0.05, 0.05, 0.05])
