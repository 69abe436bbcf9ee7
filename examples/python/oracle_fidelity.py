#!/usr/bin/env python3
"""Does a table reproduce the thesis' choices on slopes and stairs? Footstep plans with one table, drawn from above.

Thesis 2.4.2 (Fig. 2.8): with oracles learned in physics simulation the planner went straight up slopes of 10 and
20 degrees but along a curved, shallower path at 25 degrees, and on the stairs it preferred the six low steps to
the three high ones: energy grew faster than linearly with step height. Cairn's analytic model climbs every slope
straight and takes the high steps (benchmarks/RESULTS.md). This plans the four scenarios with the chosen table and
reports, for each slope, how far the path strays sideways from the straight line and the largest step up, and for
the stairs which flight the plan climbs and its steps up; it draws the plans' footholds over the terrain.

    PYTHONPATH=build/python python3 examples/python/oracle_fidelity.py --out build/fidelity.png \\
        [--source plant --oracle climb.oracle --grid examples/oracle/plant_climb_grid.yaml --t-ds 0.2,0.5 --t-sw 0.9]

Plans are not refined (the refinement optimises the analytic model's cost) and end at the scenarios' time limits,
so a run takes under a minute.
"""

import argparse
import os

import numpy as np

import cairn.planning as planning
from oracle_tables import (ROOT, add_table_arguments, check_table_arguments, load_oracle, load_robot,
                           write_outputs)

SCENARIOS = ["slope_10.yaml", "slope_20.yaml", "slope_25.yaml", "stairs.yaml"]


def footholds(plan):
    """Every foothold of the plan in order: the start stance's two feet, then each step's landing pose."""
    start = plan.StanceAfter(-1)
    poses = [start.left, start.right] + [step.pose for step in plan.steps]
    return np.array([[p.x, p.y, p.z] for p in poses])


def describe(name, plan):
    """The plan's figures: steps, cost, sideways excursion, steps up and (stairs) the flight it climbs."""
    entry = {"scenario": name, "found": plan.found, "reason": plan.reason}
    if not plan.found:
        return entry
    feet = footholds(plan)
    rises = [step.displacement.dz for step in plan.steps]
    entry.update({"steps": len(plan.steps), "cost": plan.cost, "energy_J": plan.energy,
                  "max_step_up_m": max(rises), "steps_up": sum(1 for dz in rises if dz > 0.02),
                  "max_sideways_m": float(np.max(np.abs(feet[:, 1])))})
    if name.startswith("stairs"):
        # The wall between the flights stands at |y| < 0.2 from x = 1 to 2.5: left is the high flight, right the low.
        on_flight = feet[(feet[:, 0] > 1.0) & (feet[:, 0] < 2.5)]
        entry["flight"] = ("high (left)" if on_flight[:, 1].mean() > 0 else "low (right)") if len(on_flight) else "none"
    return entry


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_table_arguments(parser)
    parser.add_argument("--out", default="oracle_fidelity.png", help="PNG to write")
    parser.add_argument("--json", help="also write the figures as JSON")
    args = parser.parse_args()
    check_table_arguments(parser, args)
    model, robot, controller = load_robot()
    objective = planning.WalkingObjective.kComWorkPlusHeat
    oracle = load_oracle(args, model, objective, robot, controller)
    print(f"oracle: {oracle.description()}")
    geometry = planning.BipedGeometry.FromWalkingModel(model)

    report = {"oracle": oracle.description(), "scenarios": []}
    plans = []
    for file in SCENARIOS:
        scenario = planning.FootstepScenario.Load(os.path.join(ROOT, "examples", "scenarios", file))
        terrain = scenario.BuildTerrain()
        plan = planning.PlanFootsteps(terrain, scenario.start(), scenario.goal(), oracle, geometry, scenario.planner())
        name = os.path.splitext(file)[0]
        entry = describe(name, plan)
        report["scenarios"].append(entry)
        plans.append((name, plan))
        if not plan.found:
            print(f"{name:>9}: no plan: {plan.reason}")
            continue
        extra = f", climbs the {entry['flight']} flight" if "flight" in entry else ""
        print(f"{name:>9}: {entry['steps']} steps, {entry['energy_J']:.0f} J, largest step up "
              f"{entry['max_step_up_m']:.3f} m ({entry['steps_up']} steps up), strays up to "
              f"{entry['max_sideways_m']:.2f} m sideways{extra}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle
    fig, axes = plt.subplots(1, len(plans), figsize=(4 * len(plans), 4.6), sharey=True)
    for ax, (name, plan) in zip(axes, plans):
        if plan.found:
            feet = footholds(plan)
            points = ax.scatter(feet[:, 0], feet[:, 1], c=feet[:, 2], cmap="viridis", s=14, zorder=3)
            ax.plot(feet[:, 0], feet[:, 1], color="grey", linewidth=0.6, zorder=2)
            fig.colorbar(points, ax=ax, label="foothold height (m)", fraction=0.05)
        else:
            ax.text(0.5, 0.5, "no plan", transform=ax.transAxes, ha="center")
        if name.startswith("stairs"):
            ax.add_patch(Rectangle((1.0, -0.2), 1.5, 0.4, color="lightgrey", zorder=1, label="wall"))
            ax.add_patch(Rectangle((1.0, 0.2), 1.5, 0.8, fill=False, edgecolor="tab:red", zorder=1,
                                   label="3 high steps (0.14 m)"))
            ax.add_patch(Rectangle((1.0, -1.0), 1.5, 0.8, fill=False, edgecolor="tab:blue", zorder=1,
                                   label="6 low steps (0.07 m)"))
            ax.legend(loc="lower right", fontsize=6)
        ax.set_title(name.replace("_", " "))
        ax.set_xlabel("x, uphill (m)")
        ax.set_aspect("equal")
        ax.set_xlim(-0.3, 3.3)
        ax.set_ylim(-1.2, 1.2)
        ax.grid(True, linewidth=0.3)
    axes[0].set_ylabel("y (m)")
    source = oracle.source().split()[0]
    fig.suptitle(f"Footstep plans with the {source} table: slopes of 10, 20, 25 degrees and the stairs")
    fig.tight_layout()
    write_outputs(fig, args.out, report, args.json, dpi=100)


if __name__ == "__main__":
    main()
