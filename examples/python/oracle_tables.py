"""What the oracle examples share: the robot, the table chosen on the command line, and atomic JSON/PNG output.

A table is the `model` source's default table (built on the first run into --oracle-cache, then read), or a `plant`
or `pipeline` table read from --oracle with the source settings it was built with (`cairn oracle build`).
"""

import json
import math
import os

import cairn
import cairn.multibody as mb
import cairn.planning as planning

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SOURCES = ["model", "plant", "pipeline"]


def add_table_arguments(parser):
    """The options that choose a table: --source, --oracle and the gait sources' timings and grid."""
    parser.add_argument("--source", choices=SOURCES, default="model",
                        help="the oracle's source (plant and pipeline need --oracle)")
    parser.add_argument("--oracle", help="the plant or pipeline table's file")
    parser.add_argument("--t-ds", help="the gait table's double-support times, comma-separated")
    parser.add_argument("--t-sw", help="the gait table's swing times, comma-separated")
    parser.add_argument("--grid", help="the gait table's grid YAML")
    parser.add_argument("--oracle-cache", default=os.path.join(os.path.expanduser("~"), ".cache", "cairn", "oracles"))


def check_table_arguments(parser, args):
    """Usage errors: a gait source without its table, or a table for the model source."""
    if (args.source == "model") != (args.oracle is None):
        parser.error(f"--source {args.source} " + ("takes no --oracle; drop it or give --source plant|pipeline"
                                                   if args.oracle else "needs --oracle FILE (cairn oracle build)"))


def load_robot():
    """The walking model, the floating-base humanoid and its joint controller from the data folder."""
    data = cairn.data_dir() or os.path.join(ROOT, "data")
    model = planning.WalkingModel.Load(os.path.join(data, "robots", "cairn_humanoid_walking.yaml"))
    options = mb.UrdfOptions()
    options.floating_base = True
    robot = mb.ParseUrdfFile(os.path.join(data, "robots", "cairn_humanoid.urdf"), options)
    controller = mb.JointPdController.Load(robot, os.path.join(data, "robots", "cairn_humanoid_control.yaml"))
    return model, robot, controller


def load_oracle(args, model, objective, robot, controller):
    """The analytic default table from the cache, or the gait table of --oracle with its source's settings."""
    if args.source == "model":
        os.makedirs(args.oracle_cache, exist_ok=True)
        path = os.path.join(args.oracle_cache, f"{model.name()}-{planning.to_string(objective)}.oracle")
        oracle, log = planning.TransitionOracle.LoadOrBuild(path, model, objective, planning.OracleGrid.Default(model))
        print(log.strip())
        return oracle
    sampler = planning.PlantGaitSampler(model, robot, controller, objective)
    t_ds = [float(v) for v in args.t_ds.split(",")] if args.t_ds else planning.PlantTransitionSource.DefaultDoubleSupportTimes(model)
    t_sw = [float(v) for v in args.t_sw.split(",")] if args.t_sw else planning.PlantTransitionSource.DefaultSwingTimes(model)
    mode = {"plant": planning.PlantTransitionSource.Mode.kPlant,
            "pipeline": planning.PlantTransitionSource.Mode.kPipeline}[args.source]
    source = planning.PlantTransitionSource(sampler, t_ds, t_sw, mode)
    grid = planning.OracleGrid.Load(args.grid) if args.grid else planning.PlantTransitionSource.DefaultGrid(model)
    return planning.TransitionOracle.Load(args.oracle, model, objective, grid, source)


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


def write_outputs(figure, png_path, report, json_path=None, dpi=110):
    """The figure as a PNG and, with `json_path`, the report as sorted, indented JSON; each written atomically."""
    write_atomically(png_path, lambda path: figure.savefig(path, dpi=dpi, format="png"))
    print(f"wrote {png_path}")
    if json_path:
        text = json.dumps(finite_or_none(report), indent=1, sort_keys=True) + "\n"

        def write(temporary):
            with open(temporary, "w") as f:
                f.write(text)

        write_atomically(json_path, write)
        print(f"wrote {json_path}")
