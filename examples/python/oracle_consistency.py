#!/usr/bin/env python3
"""How well a transition oracle predicts what the whole pipeline spends: plans walked in the plant, step by step.

For each scenario the walk diagram plans footsteps with the oracle, optimises the whole body, stabilises and walks
the plan in the physics plant (as `cairn walk`); every step that was walked to the end of its planned window gives
the oracle's predicted energy (E_COM + motor heat) and RCOF against the plant's (E_COM + Joule heat over the
window, the net-force RCOF). Prints, per scenario and over all, the mean error, the mean absolute error and the
correlation (issue 21's objective-consistency report), and draws predicted against measured energy.

    PYTHONPATH=build/python python3 examples/python/oracle_consistency.py --out build/consistency.png \
        [--oracle plant.oracle --t-ds 0.5 --t-sw 1.2 --grid grid.yaml] [--json consistency.json] [scenario.yaml ...]

Without --oracle the analytic model's default table is used (built on the first run, then read from
--oracle-cache); with --oracle, a plant table built by `cairn oracle build --source plant` with the same timings and
grid. Each walk takes about a minute.
"""

import argparse
import json
import math
import os

import numpy as np

import cairn
import cairn.multibody as mb
import cairn.planning as planning

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DEFAULT_SCENARIOS = ["flat.yaml", "ice_narrow_006.yaml", "stairs.yaml"]


def statistics(pairs):
    """Mean error, mean absolute error and correlation of (predicted, measured) pairs (NaN where undefined)."""
    if not pairs:
        return {"steps": 0, "mean_error": math.nan, "mean_absolute_error": math.nan, "correlation": math.nan}
    predicted, measured = np.array(pairs).T
    error = predicted - measured
    correlation = math.nan
    if len(pairs) > 1 and np.std(predicted) > 0 and np.std(measured) > 0:
        correlation = float(np.corrcoef(predicted, measured)[0, 1])
    return {"steps": len(pairs), "mean_error": float(error.mean()), "mean_absolute_error": float(abs(error).mean()),
            "correlation": correlation}


def finite_or_none(value):
    """JSON has no NaN: undefined figures are written as null."""
    if isinstance(value, dict):
        return {k: finite_or_none(v) for k, v in value.items()}
    if isinstance(value, list):
        return [finite_or_none(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def write_atomically(path, write):
    """Writes through a temporary file beside `path` and renames it, so a reader never sees half a file."""
    temporary = f"{path}.tmp.{os.getpid()}"
    try:
        write(temporary)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def load_oracle(args, model, objective, robot, controller):
    """The analytic default table from the cache, or the plant table of --oracle with its source's settings."""
    if not args.oracle:
        os.makedirs(args.oracle_cache, exist_ok=True)
        path = os.path.join(args.oracle_cache, f"{model.name()}-{planning.to_string(objective)}.oracle")
        oracle, log = planning.TransitionOracle.LoadOrBuild(path, model, objective, planning.OracleGrid.Default(model))
        print(log.strip())
        return oracle
    sampler = planning.PlantGaitSampler(model, robot, controller, objective)
    t_ds = [float(v) for v in args.t_ds.split(",")] if args.t_ds else planning.PlantTransitionSource.DefaultDoubleSupportTimes(model)
    t_sw = [float(v) for v in args.t_sw.split(",")] if args.t_sw else planning.PlantTransitionSource.DefaultSwingTimes(model)
    source = planning.PlantTransitionSource(sampler, t_ds, t_sw)
    grid = planning.OracleGrid.Load(args.grid) if args.grid else planning.PlantTransitionSource.DefaultGrid(model)
    return planning.TransitionOracle.Load(args.oracle, model, objective, grid, source)


def walk(scenario_path, oracle, model, robot, controller, plant_priced):
    """Walks one scenario; returns its record and its step comparisons."""
    scenario = planning.FootstepScenario.Load(scenario_path)
    objective = planning.ParseWalkingObjective(scenario.objective())
    setup = planning.WalkSetupFromScenario(scenario, oracle, model, objective, robot, controller)
    if plant_priced:
        setup.refine_model = None  # the refinement optimises the analytic model's cost, not the plant's
    diagram = planning.BuildWalkDiagram(setup)
    record = planning.RunWalk(diagram)
    return record, planning.CompareWalkSteps(record)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenarios", nargs="*", help="footstep scenario YAML files (default: flat, narrow ice, stairs)")
    parser.add_argument("--oracle", help="a plant oracle file (default: the analytic model's table)")
    parser.add_argument("--t-ds", help="the plant table's double-support times, comma-separated")
    parser.add_argument("--t-sw", help="the plant table's swing times, comma-separated")
    parser.add_argument("--grid", help="the plant table's grid YAML")
    parser.add_argument("--oracle-cache", default=os.path.join(os.path.expanduser("~"), ".cache", "cairn", "oracles"))
    parser.add_argument("--out", default="oracle_consistency.png", help="PNG to write")
    parser.add_argument("--json", help="also write the figures as JSON")
    args = parser.parse_args()

    data = cairn.data_dir() or os.path.join(ROOT, "data")
    model = planning.WalkingModel.Load(os.path.join(data, "robots", "cairn_humanoid_walking.yaml"))
    options = mb.UrdfOptions()
    options.floating_base = True
    robot = mb.ParseUrdfFile(os.path.join(data, "robots", "cairn_humanoid.urdf"), options)
    controller = mb.JointPdController.Load(robot, os.path.join(data, "robots", "cairn_humanoid_control.yaml"))
    scenarios = args.scenarios or [os.path.join(ROOT, "examples", "scenarios", s) for s in DEFAULT_SCENARIOS]
    objective = planning.WalkingObjective.kComWorkPlusHeat
    oracle = load_oracle(args, model, objective, robot, controller)
    print(f"oracle: {oracle.description()}")

    report = {"oracle": oracle.description(), "scenarios": []}
    energy_all, rcof_all = [], []
    series = []
    for path in scenarios:
        record, steps = walk(path, oracle, model, robot, controller, bool(args.oracle))
        walked = [s for s in steps if s.completed]
        energy = [(s.predicted_com_work + s.predicted_heat, s.measured_com_energy + s.measured_heat) for s in walked]
        rcof = [(s.predicted_rcof, s.measured_net_rcof) for s in walked]
        energy_all += energy
        rcof_all += rcof
        name = os.path.splitext(os.path.basename(path))[0]
        series.append((name, energy))
        entry = {"scenario": name, "planned": record.start.ready, "reason": record.start.reason,
                 "steps": len(steps), "walked_steps": len(walked), "fell": record.fell,
                 "energy_J": statistics(energy), "rcof": statistics(rcof)}
        report["scenarios"].append(entry)
        e = entry["energy_J"]
        if not record.start.ready:
            print(f"{name:>16}: not walked: {record.start.reason}")
            continue
        print(f"{name:>16}: {len(walked)}/{len(steps)} steps walked{' (fell)' if record.fell else ''}; energy "
              f"mean error {e['mean_error']:.1f} J, |error| {e['mean_absolute_error']:.1f} J, "
              f"correlation {e['correlation']:.2f}")
    report["all"] = {"energy_J": statistics(energy_all), "rcof": statistics(rcof_all)}
    e, r = report["all"]["energy_J"], report["all"]["rcof"]
    print(f"{'all':>16}: {e['steps']} steps; energy mean error {e['mean_error']:.1f} J, |error| "
          f"{e['mean_absolute_error']:.1f} J, correlation {e['correlation']:.2f}; RCOF mean error "
          f"{r['mean_error']:.3f}, correlation {r['correlation']:.2f}")

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
    ax.set_xlabel("measured in the plant: E_COM + Joule heat per step (J)")
    ax.set_ylabel("predicted by the oracle: E_COM + motor heat per step (J)")
    ax.set_title(f"Oracle consistency ({'plant' if args.oracle else 'model'} table), {e['steps']} steps")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(True, linewidth=0.3)
    fig.tight_layout()
    write_atomically(args.out, lambda path: fig.savefig(path, dpi=110, format="png"))
    print(f"wrote {args.out}")
    if args.json:
        text = json.dumps(finite_or_none(report), indent=1, sort_keys=True) + "\n"

        def write_json(path):
            with open(path, "w") as f:
                f.write(text)

        write_atomically(args.json, write_json)
        print(f"wrote {args.json}")


if __name__ == "__main__":
    main()
