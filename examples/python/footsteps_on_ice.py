#!/usr/bin/env python3
"""Energy- and friction-aware footstep planning across an ice patch, plotted with matplotlib.

Loads a scenario (default: the thesis' narrow ice patch, mu 0.12, examples/scenarios/ice_narrow_012.yaml), the
project's humanoid and its transition oracle (built on the first run, ~15 s, then read from --oracle-cache), plans
with ARA* under an expansion budget, and draws the terrain's usable friction with the footsteps on it.

    PYTHONPATH=build/python python3 examples/python/footsteps_on_ice.py --out build/ice.png [--json plan.json]
"""

import argparse
import json
import math
import os
import sys

import numpy as np

import cairn
import cairn.planning as planning

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def foot_outline(pose, length, width):
    """The sole's corners (closed polygon) at a foothold."""
    c, s = math.cos(pose.theta), math.sin(pose.theta)
    corners = [(length / 2, width / 2), (-length / 2, width / 2), (-length / 2, -width / 2), (length / 2, -width / 2)]
    points = [(pose.x + c * dx - s * dy, pose.y + s * dx + c * dy) for dx, dy in corners]
    return np.array(points + points[:1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=os.path.join(ROOT, "examples", "scenarios", "ice_narrow_012.yaml"))
    parser.add_argument("--oracle-cache", default=os.path.join(os.path.expanduser("~"), ".cache", "cairn", "oracles"))
    parser.add_argument("--max-expansions", type=int, default=50000, help="ARA* budget (reproducible)")
    parser.add_argument("--out", default="footsteps_on_ice.png", help="PNG to write")
    parser.add_argument("--json", help="also write the plan as JSON")
    args = parser.parse_args()

    scenario = planning.FootstepScenario.Load(args.scenario)
    data = cairn.data_dir() or os.path.join(ROOT, "data")
    robot = scenario.robot() or os.path.join(data, "robots", "cairn_humanoid_walking.yaml")
    model = planning.WalkingModel.Load(robot)
    objective = planning.ParseWalkingObjective(scenario.objective())
    os.makedirs(args.oracle_cache, exist_ok=True)
    oracle_path = os.path.join(args.oracle_cache, f"{model.name()}-{planning.to_string(objective)}.oracle")
    oracle, log = planning.TransitionOracle.LoadOrBuild(oracle_path, model, objective,
                                                        planning.OracleGrid.Default(model))
    if log:
        print(log.strip())

    terrain = scenario.BuildTerrain()
    geometry = planning.BipedGeometry.FromWalkingModel(model)
    options = scenario.planner()
    options.search.max_expansions = args.max_expansions
    options.search.time_limit = float("inf")
    plan = planning.PlanFootsteps(terrain, scenario.start(), scenario.goal(), oracle, geometry, options)
    if not plan.found:
        print(f"no plan: {plan.reason}")
        return 1
    planning.RefineFootstepPlan(model, objective, plan)
    print(f"{scenario.name()}: {len(plan.steps)} steps, {plan.distance:.2f} m, {plan.duration:.1f} s, "
          f"energy {plan.energy:.0f} J, max RCOF {plan.max_rcof:.3f}, bound epsilon {plan.statistics.epsilon:.2f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(9, 5))
    lo, hi = terrain.origin(), terrain.max_corner()
    image = axes.imshow(terrain.frictions(), origin="lower", extent=(lo[0], hi[0], lo[1], hi[1]), cmap="Blues_r",
                        vmin=0.0, vmax=1.0)
    figure.colorbar(image, ax=axes, label="usable friction $Q_{1-\\eta}(\\mu)$")
    for k, pose in enumerate([plan.start.left, plan.start.right]):
        outline = foot_outline(pose, geometry.foot_length, geometry.foot_width)
        axes.plot(outline[:, 0], outline[:, 1], color="black", linewidth=1.5)
    for step in plan.steps:
        outline = foot_outline(step.pose, geometry.foot_length, geometry.foot_width)
        color = "tab:red" if step.side == planning.FootSide.kLeft else "tab:green"
        axes.fill(outline[:, 0], outline[:, 1], color=color, alpha=0.6)
    axes.set_aspect("equal")
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    axes.set_title(f"{scenario.name()}: {len(plan.steps)} steps, {plan.energy:.0f} J (left red, right green)")
    figure.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    figure.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")
    if args.json:
        with open(args.json, "w") as out:
            json.dump(plan.to_dict(), out, indent=1)
        print(f"wrote {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
