"""Run by run_install_import.cmake with PYTHONPATH set to an install prefix's site-packages folder only."""

import os
import sys

import numpy as np

prefix = os.path.realpath(sys.argv[1])
import cairn  # noqa: E402
from cairn import multibody, optimization, perception, planning, systems  # noqa: E402


def inside(path):
    return os.path.realpath(path).startswith(prefix + os.sep)


assert inside(cairn.__file__), f"cairn imported from {cairn.__file__}, not from {prefix}"
assert inside(cairn._cairn.__file__), cairn._cairn.__file__


class Twice(systems.LeafSystem):
    def __init__(self):
        super().__init__()
        self.u = self.DeclareVectorInputPort("u", 1)
        self.DeclareVectorOutputPort("y", 1, lambda context, y: 2.0 * self.u.Eval(context))


builder = systems.DiagramBuilder()
source = builder.AddSystem(systems.ConstantVectorSource(np.array([1.5])))
twice = builder.AddSystem(Twice())
builder.Connect(source.get_output_port(0), twice.get_input_port(0))
builder.ExportOutput(twice.get_output_port(0), "y")
diagram = builder.Build()
assert diagram.GetOutputPort("y").Eval(diagram.CreateDefaultContext())[0] == 3.0

prog = optimization.MathematicalProgram()
x = prog.NewContinuousVariables(1, "x")
prog.AddCost(lambda v: (v[0] - 2.0) ** 2, x)
assert abs(optimization.Solve(prog).x[0] - 2.0) < 1e-6

builder = multibody.ModelBuilder("one")
assert builder.Build().num_bodies() == 1
assert perception.FrictionDistribution.Normal(0.5, 0.1).Mean() == 0.5
assert planning.FootPose(x=1.0).x == 1.0

# Every Cairn library the process loaded comes from the prefix (its RPATH), not from the build tree.
with open("/proc/self/maps") as maps:
    libraries = {line.split()[-1] for line in maps if "libcairn_" in line}
assert libraries, "no Cairn library loaded"
outside = [path for path in libraries if not inside(path)]
assert not outside, f"loaded from outside the prefix: {outside}"
print(f"installed cairn: every submodule ran from {prefix} ({len(libraries)} Cairn libraries)")
