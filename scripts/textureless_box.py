#!/usr/bin/env python3
"""Thesis Fig. 5.5's failure case, measured: a box without texture on a textured floor, seen by the main diagram's
head camera (one frame, 320x240), fused into occupancy by the WTA range model and by the cost-curve model, and
assembled into the planner's terrain from each. Prints, per model, how the grid sees the box's volume (mean
occupancy probability, share of its cells occupied and free) and what the terrain makes of its top (median
height, share without ground, occupied voxels). `--contrast C` gives the box a texture of that contrast (0: none).

    PYTHONPATH=build/python /usr/bin/python3 scripts/textureless_box.py [--contrast 0]

Measured 2026-12-05 (docs/main_diagram.md): with no texture both models see most of the box as free space, and the
cost-curve model more so (thesis eqs. 4.13-4.17 assume a surface on every ray, equally likely in every cell, so a
flat cost curve makes the cells near the camera free); the thesis' claim, that cost-curve probabilities keep such an obstacle
where WTA loses it, does not hold for this scene.
"""

import argparse
import os

import numpy as np

import cairn.perception as perception
import cairn.planning as planning

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--contrast", type=float, default=0.0, help="the box's texture contrast (0: none)")
    args = parser.parse_args()
    if not 0.0 <= args.contrast <= 255.0:
        parser.error(f"--contrast {args.contrast} must be in [0, 255]")

    camera = planning.SyntheticCamera()
    calibration = camera.Calibration()
    start = planning.FootstepScenario.Load(os.path.join(SOURCE_DIR, "examples/scenarios/mockup/mockup.yaml")).start()
    X_WC = planning.ScenarioCameraPose(start, camera.head)
    scene = perception.SyntheticStereoScene()
    scene.AddPlane(np.zeros(3), np.array([0.0, 0.0, 1.0]), perception.ProceduralTexture(), 1)
    box_texture = perception.ProceduralTexture()
    box_texture.contrast = args.contrast
    X_WB = np.eye(4)
    X_WB[:3, 3] = [0.7, 0.0, 0.1]  # 30 x 60 x 20 cm, 0.55-0.85 m ahead
    scene.AddBox(X_WB, np.array([0.15, 0.3, 0.1]), box_texture, 2)
    frame = perception.SyntheticStereoRenderer(calibration, camera.width, camera.height, camera.noise_variance, 1).Render(
        scene, X_WC, 0)

    options = perception.StereoMatcher.Options()
    fb = calibration.depth_times_disparity()
    options.cost_volume.min_disparity = int(fb / 4.0)
    options.cost_volume.max_disparity = int(np.ceil(fb / 0.5))
    matcher = perception.StereoMatcher(options)
    context = matcher.CreateDefaultContext()
    matcher.GetInputPort("left").FixValue(context, frame.left)
    matcher.GetInputPort("right").FixValue(context, frame.right)
    wta = matcher.GetOutputPort("wta").Eval(context)
    confidence = matcher.GetOutputPort("confidence").Eval(context)

    def grid():
        return perception.OccupancyGrid(np.array([-0.6, -0.9, -0.1]), 0.025, np.array([96, 72, 44]))

    grids = {"WTA range model": grid(), "cost-curve model": grid()}
    perception.WtaRangeSensorModel().Integrate(wta, options.cost_volume.min_disparity,
                                               options.cost_volume.max_disparity, calibration, X_WC,
                                               grids["WTA range model"])
    perception.CostCurveSensorModel().Integrate(confidence, calibration, X_WC, grids["cost-curve model"])
    registry = perception.MaterialRegistry.ThesisTable33()
    no_points = perception.FrictionPointCloud(np.zeros((0, 3)), np.zeros(0, dtype=np.float32),
                                              np.zeros((0, registry.size()), dtype=np.float32))
    assembly = planning.TerrainAssemblyOptions()
    assembly.unknown_friction = 0.5  # geometry only: no material is perceived here
    print(f"box contrast {args.contrast:g}: its top at 0.200 m")
    for name, g in grids.items():
        inside = np.array([g.probability(g.Index(g.CellOf(np.array([x, y, z]))))
                           for x in np.arange(0.5625, 0.85, 0.025)
                           for y in np.arange(-0.2875, 0.3, 0.025)
                           for z in np.arange(0.0375, 0.2, 0.025)])
        terrain = planning.AssembleTerrain(g, no_points, registry, assembly)
        tops = np.array([terrain.height(*terrain.CellAt(x, y))
                         for x in np.arange(0.6, 0.8, 0.05) for y in np.arange(-0.25, 0.25, 0.05)])
        _, probabilities = terrain.occupied_voxels()
        seen = tops[~np.isnan(tops)]
        median = f"{np.median(seen):.3f} m" if seen.size else "none"
        print(f"{name:17s} box volume: mean p {inside.mean():.2f}, occupied {np.mean(inside > 0.5):.2f}, "
              f"free {np.mean(inside < 0.5):.2f}; terrain on its top: median height {median}, "
              f"no ground {np.mean(np.isnan(tops)):.2f}; {len(probabilities)} occupied voxels")


if __name__ == "__main__":
    main()
