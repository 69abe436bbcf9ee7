#!/usr/bin/env python3
"""How well a transition oracle predicts what the whole pipeline spends: plans walked in the plant, step by step.

For each scenario the walk diagram plans footsteps with the oracle, optimises the whole body, stabilises and walks
the plan in the physics plant (as `cairn walk`); every step that was walked to the end of its planned window gives
the oracle's predicted cost and RCOF against what the pipeline spent: for the `model` and `plant` sources the
energy E_COM + heat (the plant's E_COM + Joule heat over the window), for the `pipeline` source the whole-body
optimiser's torque cost of the step's waypoints (every step of the optimised plan, walked or not). RCOF is always
the plant's net-force RCOF over the walked steps. Prints, per scenario and over all, the mean error, the mean
absolute error and the correlation (issue 21's objective-consistency report), and draws predicted against measured
cost.

    PYTHONPATH=build/python python3 examples/python/oracle_consistency.py --out build/consistency.png \
        [--source plant|pipeline --oracle table.oracle --t-ds 0.5 --t-sw 1.2 --grid grid.yaml] \
        [--json consistency.json] [scenario.yaml ...]

The `model` source's default table is built on the first run, then read from --oracle-cache; a `plant` or `pipeline`
table is read from --oracle, built by `cairn oracle build --source plant` (objective ecom_heat) or
`--source pipeline --objective torque` with the same timings and grid. Each walk takes about a minute.
"""

import argparse
import math
import os

import numpy as np

import cairn.planning as planning
from oracle_tables import (ROOT, add_table_arguments, check_table_arguments, load_oracle, load_robot,
                           write_outputs)

DEFAULT_SCENARIOS = ["flat.yaml", "ice_narrow_006.yaml", "stairs.yaml"]


def statistics(pairs):
    """Mean error, mean absolute error, correlation and ranges of (predicted, measured) pairs (NaN where undefined)."""
    if not pairs:
        return {"steps": 0, "mean_error": math.nan, "mean_absolute_error": math.nan, "correlation": math.nan}
    predicted, measured = np.array(pairs).T
    error = predicted - measured
    correlation = math.nan
    if len(pairs) > 1 and np.std(predicted) > 0 and np.std(measured) > 0:
        correlation = float(np.corrcoef(predicted, measured)[0, 1])
    return {"steps": len(pairs), "mean_error": float(error.mean()), "mean_absolute_error": float(abs(error).mean()),
            "correlation": correlation, "predicted_range": [float(predicted.min()), float(predicted.max())],
            "measured_range": [float(measured.min()), float(measured.max())]}


def walk(scenario_path, oracle, model, objective, robot, controller, measured_source):
    """Walks one scenario; returns its record and its step comparisons."""
    scenario = planning.FootstepScenario.Load(scenario_path)
    setup = planning.WalkSetupFromScenario(scenario, oracle, model, objective, robot, controller)
    if measured_source:
        setup.refine_model = None  # the refinement optimises the analytic model's cost, not the table's source's
    diagram = planning.BuildWalkDiagram(setup)
    record = planning.RunWalk(diagram)
    return record, planning.CompareWalkSteps(record)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenarios", nargs="*", help="footstep scenario YAML files (default: flat, narrow ice, stairs)")
    add_table_arguments(parser)
    parser.add_argument("--out", default="oracle_consistency.png", help="PNG to write")
    parser.add_argument("--json", help="also write the figures as JSON")
    args = parser.parse_args()
    check_table_arguments(parser, args)
    model, robot, controller = load_robot()
    scenarios = args.scenarios or [os.path.join(ROOT, "examples", "scenarios", s) for s in DEFAULT_SCENARIOS]
    # The pipeline's table prices the whole-body torque cost; the others the energy the plant spends.
    torque = args.source == "pipeline"
    objective = planning.WalkingObjective.kSquaredTorque if torque else planning.WalkingObjective.kComWorkPlusHeat
    unit = "" if torque else " J"
    oracle = load_oracle(args, model, objective, robot, controller)
    print(f"oracle: {oracle.description()}")

    report = {"oracle": oracle.description(), "scenarios": []}
    energy_all, rcof_all = [], []
    series = []
    for path in scenarios:
        record, steps = walk(path, oracle, model, objective, robot, controller, args.source != "model")
        walked = [s for s in steps if s.completed]
        if torque:
            # The whole-body cost needs no walk: every step of an optimised plan counts. Step k leaves stance k - 1;
            # its waypoints are that stance's start and its mid-swing.
            planned = steps if record.trajectory.found else []
            energy = [(record.plan.steps[s.index - 1].transition.cost,
                       sum(w.torque_cost for w in record.trajectory.waypoints if w.stance == s.index - 1))
                      for s in planned]
        else:
            energy = [(s.predicted_com_work + s.predicted_heat, s.measured_com_energy + s.measured_heat)
                      for s in walked]
        rcof = [(s.predicted_rcof, s.measured_net_rcof) for s in walked]
        energy_all += energy
        rcof_all += rcof
        name = os.path.splitext(os.path.basename(path))[0]
        series.append((name, energy))
        entry = {"scenario": name, "planned": record.start.ready, "reason": record.start.reason,
                 "steps": len(steps), "walked_steps": len(walked), "fell": record.fell,
                 "cost": statistics(energy), "rcof": statistics(rcof)}
        report["scenarios"].append(entry)
        e = entry["cost"]
        if not record.start.ready:
            print(f"{name:>16}: not walked: {record.start.reason}")
            continue
        print(f"{name:>16}: {len(walked)}/{len(steps)} steps walked{' (fell)' if record.fell else ''}; "
              f"{e['steps']} steps compared; cost mean error {e['mean_error']:.3g}{unit}, |error| {e['mean_absolute_error']:.3g}{unit}, "
              f"correlation {e['correlation']:.2f}")
    report["all"] = {"cost": statistics(energy_all), "rcof": statistics(rcof_all)}
    report["cost"] = "whole-body torque cost per step" if torque else "E_COM + heat per step, J"
    e, r = report["all"]["cost"], report["all"]["rcof"]
    print(f"{'all':>16}: {e['steps']} steps; cost mean error {e['mean_error']:.3g}{unit}, |error| "
          f"{e['mean_absolute_error']:.3g}{unit}, correlation {e['correlation']:.2f}; RCOF mean error "
          f"{r['mean_error']:.3f}, correlation {r['correlation']:.2f}")
    if e["steps"]:
        print(f"{'':>16}  predicted {e['predicted_range'][0]:.3g}-{e['predicted_range'][1]:.3g}{unit}, measured "
              f"{e['measured_range'][0]:.3g}-{e['measured_range'][1]:.3g}{unit} a step")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 6))
    for name, pairs in series:
        if pairs:
            predicted, measured = np.array(pairs).T
            ax.scatter(measured, predicted, s=18, label=name)
    values = [v for pair in energy_all for v in pair]
    if values:
        lo, hi = min(values), max(values)
        ax.plot([lo, hi], [lo, hi], color="grey", linewidth=1, label="perfect prediction")
    if torque:
        ax.set_xlabel("spent by the whole-body optimiser: torque cost of the step's waypoints")
        ax.set_ylabel("predicted by the oracle: torque cost per step")
    else:
        ax.set_xlabel("measured in the plant: E_COM + Joule heat per step (J)")
        ax.set_ylabel("predicted by the oracle: E_COM + motor heat per step (J)")
    ax.set_title(f"Oracle consistency ({args.source} table), {e['steps']} steps")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(True, linewidth=0.3)
    fig.tight_layout()
    write_outputs(fig, args.out, report, args.json, dpi=110)


if __name__ == "__main__":
    main()
