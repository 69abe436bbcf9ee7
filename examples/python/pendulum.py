#!/usr/bin/env python3
"""The pendulum diagram of examples/systems with its PD controller written in Python.

    plant.state -> hold (ZeroOrderHold, 1 ms) -> controller (Python) -> plant.torque;  plant.state -> logger

The plant, the hold and the logger are C++ systems; the controller is a cairn.systems.LeafSystem subclass that the
simulator calls back every millisecond. The run prints the final state and the equilibrium the controller should
settle at (kp (theta_d - theta) = m g l sin theta); --plot writes the trajectory as a PNG (matplotlib).

    PYTHONPATH=build/python python3 examples/python/pendulum.py [--duration 10] [--plot pendulum.png]
"""

import argparse
import math
import sys

import numpy as np

from cairn.examples import PendulumParameters, PendulumPlant
from cairn.systems import DiagramBuilder, LeafSystem, LogVectorOutput, Simulator, ZeroOrderHold


class PdController(LeafSystem):
    """tau = kp (theta_d - theta) - kd theta': input `state` (theta, theta'), output `torque`."""

    def __init__(self, kp, kd, theta_desired):
        super().__init__()
        self.state = self.DeclareVectorInputPort("state", 2)
        self.DeclareNumericParameter([kp, kd, theta_desired])
        self.DeclareVectorOutputPort("torque", 1, self.CalcTorque)

    def CalcTorque(self, context, torque):
        kp, kd, theta_desired = context.get_numeric_parameter(0)
        theta, theta_dot = self.state.Eval(context)
        torque[0] = kp * (theta_desired - theta) - kd * theta_dot


def predicted_equilibrium(parameters, kp, theta_desired):
    """The theta with kp (theta_d - theta) = m g l sin(theta), by Newton's method."""
    mgl = parameters.mass * parameters.gravity * parameters.length
    theta = theta_desired
    for _ in range(50):
        f = kp * (theta_desired - theta) - mgl * math.sin(theta)
        theta -= f / (-kp - mgl * math.cos(theta))
    return theta


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=10.0, help="simulated seconds (default 10)")
    parser.add_argument("--kp", type=float, default=5.0)
    parser.add_argument("--kd", type=float, default=0.5)
    parser.add_argument("--theta-desired", type=float, default=math.pi / 4)
    parser.add_argument("--plot", help="write the trajectory to this PNG")
    args = parser.parse_args()

    parameters = PendulumParameters()
    builder = DiagramBuilder()
    plant = builder.AddNamedSystem("plant", PendulumPlant(parameters))
    hold = builder.AddNamedSystem("hold", ZeroOrderHold(0.001, 2))
    controller = builder.AddNamedSystem("controller", PdController(args.kp, args.kd, args.theta_desired))
    builder.Connect(plant.get_output_port(0), hold.get_input_port(0))
    builder.Connect(hold.get_output_port(0), controller.get_input_port(0))
    builder.Connect(controller.get_output_port(0), plant.get_input_port(0))
    logger = LogVectorOutput(plant.get_output_port(0), builder, 0.01)
    diagram = builder.Build()

    simulator = Simulator(diagram)
    status = simulator.AdvanceTo(args.duration)
    context = simulator.get_context()
    theta, theta_dot = diagram.GetSubsystemContext(plant, context).get_continuous_state_vector()
    expected = predicted_equilibrium(parameters, args.kp, args.theta_desired)
    print(f"t = {status.time:.3f} s after {simulator.num_steps_taken()} steps: theta = {theta:.6f} rad, "
          f"theta' = {theta_dot:.2e} rad/s")
    print(f"predicted equilibrium theta = {expected:.6f} rad (error {abs(theta - expected):.2e})")

    log = logger.GetLog(diagram.GetSubsystemContext(logger, context))
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        figure, axes = plt.subplots(figsize=(7, 3.5))
        axes.plot(log.sample_times(), log.data()[0], label="theta (rad)")
        axes.plot(log.sample_times(), log.data()[1], label="theta' (rad/s)")
        axes.axhline(expected, color="grey", linestyle="--", label="predicted equilibrium")
        axes.set_xlabel("time (s)")
        axes.legend()
        axes.set_title("Pendulum under a Python PD controller")
        figure.tight_layout()
        figure.savefig(args.plot, dpi=100)
        print(f"wrote {args.plot}")
    # Settled means at the equilibrium and at rest, after a long enough run.
    settled = abs(theta - expected) < 1e-3 and abs(theta_dot) < 1e-3
    return 0 if settled or args.duration < 5.0 else 1


if __name__ == "__main__":
    sys.exit(main())
