"""cairn.systems: diagrams of C++ and Python systems, contexts, events, abstract values, errors and ownership."""

import copy
import gc
import math
import weakref

import numpy as np
import pytest

import cairn
import cairn.examples as examples
from cairn.systems import (AbstractValue, Adder, ConstantValueSource, ConstantVectorSource, DiagramBuilder,
                           FunctionSystem, Gain, Integrator, LeafSystem, LogVectorOutput, MonitorResult, PassThrough,
                           Simulator, VectorLogSink, ZeroOrderHold)


class PdControllerPy(LeafSystem):
    """The C++ example's PD controller, written in Python: tau = kp (theta_d - theta) - kd theta'."""

    def __init__(self, kp, kd, theta_desired):
        super().__init__()
        self.state = self.DeclareVectorInputPort("state", 2)
        self.DeclareNumericParameter([kp, kd, theta_desired])
        self.DeclareVectorOutputPort("torque", 1, self.CalcTorque)

    def CalcTorque(self, context, torque):
        kp, kd, theta_desired = context.get_numeric_parameter(0)
        theta, theta_dot = self.state.Eval(context)
        torque[0] = kp * (theta_desired - theta) - kd * theta_dot


def build_pendulum(controller, initial_state=(0.0, 0.0)):
    """plant.state -> hold -> controller -> plant.torque, plant.state -> logger, as examples/systems does."""
    builder = DiagramBuilder()
    plant = builder.AddNamedSystem("plant", examples.PendulumPlant())
    hold = builder.AddNamedSystem("hold", ZeroOrderHold(0.001, 2))
    builder.AddNamedSystem("controller", controller)
    builder.Connect(plant.get_output_port(0), hold.get_input_port(0))
    builder.Connect(hold.get_output_port(0), controller.get_input_port(0))
    builder.Connect(controller.get_output_port(0), plant.get_input_port(0))
    logger = LogVectorOutput(plant.get_output_port(0), builder, 0.01)
    logger.set_name("logger")
    diagram = builder.Build()
    context = diagram.CreateDefaultContext()
    diagram.GetMutableSubsystemContext(plant, context).SetContinuousState(np.array(initial_state))
    return diagram, context


def simulate(diagram, context, duration):
    simulator = Simulator(diagram, context)
    status = simulator.AdvanceTo(duration)
    assert status.reached_boundary_time()
    return simulator


def test_submodules_are_importable():
    import cairn.optimization  # noqa: F401
    import cairn.perception  # noqa: F401
    import cairn.planning  # noqa: F401
    from cairn.multibody import Model  # noqa: F401

    assert cairn.systems is cairn._cairn.systems
    assert cairn.__version__.count(".") == 2


def test_cpp_primitives_compute():
    builder = DiagramBuilder()
    source = builder.AddSystem(ConstantVectorSource(np.array([1.0, 2.0, 3.0])))
    gain = builder.AddNamedSystem("gain", Gain(2.0, 3))
    adder = builder.AddSystem(Adder(2, 3))
    builder.Connect(source.get_output_port(0), gain.get_input_port(0))
    builder.Connect(gain.get_output_port(0), adder.get_input_port(0))
    builder.Connect(source.get_output_port(0), adder.get_input_port(1))
    builder.ExportOutput(adder.get_output_port(0), "y")
    diagram = builder.Build()
    context = diagram.CreateDefaultContext()
    np.testing.assert_array_equal(diagram.GetOutputPort("y").Eval(context), [3.0, 6.0, 9.0])
    assert diagram.GetSubsystemByName("gain") is gain
    assert [s.get_name() for s in diagram.GetSystems()] == [source.get_name(), "gain", adder.get_name()]
    assert "gain" in diagram.GetGraphvizString()
    source_context = diagram.GetMutableSubsystemContext(source, context)
    source.SetValue(source_context, np.array([1.0, 1.0, 1.0]))
    np.testing.assert_array_equal(diagram.GetOutputPort("y").Eval(context), [3.0, 3.0, 3.0])


def test_python_controller_in_cpp_diagram_matches_cpp_controller():
    python_diagram, python_context = build_pendulum(PdControllerPy(5.0, 0.5, math.pi / 4))
    cpp_diagram, cpp_context = build_pendulum(examples.PdController(5.0, 0.5, math.pi / 4))
    python_sim = simulate(python_diagram, python_context, 2.0)
    cpp_sim = simulate(cpp_diagram, cpp_context, 2.0)
    plant = python_diagram.GetSubsystemByName("plant")
    x_python = python_sim.get_context().get_continuous_state_vector()
    x_cpp = cpp_sim.get_context().get_continuous_state_vector()
    # The same arithmetic in Python and C++: the trajectories agree to round-off.
    np.testing.assert_allclose(x_python, x_cpp, rtol=0, atol=1e-12)
    assert x_python[0] > 0.3  # lifted towards 45 degrees against gravity
    logger = python_diagram.GetSubsystemByName("logger")
    log = logger.GetLog(python_diagram.GetSubsystemContext(logger, python_sim.get_context()))
    assert log.num_samples() == 201
    np.testing.assert_allclose(log.data()[:, -1], x_python)
    energy = plant.CalcTotalEnergy(python_diagram.GetSubsystemContext(plant, python_sim.get_context()))
    assert energy > 0.0


class PythonIntegrator(LeafSystem):
    """x' = u with continuous state, y = x: the C++ Integrator, in Python."""

    def __init__(self, size):
        super().__init__()
        self.u = self.DeclareVectorInputPort("u", size)
        self.DeclareContinuousState(np.zeros(size))
        self.DeclareVectorOutputPort("y", size, self.CalcY, prerequisites_of_calc=[self.xc_ticket()])

    def DoCalcTimeDerivatives(self, context, derivatives):
        derivatives[:] = self.u.Eval(context)

    def CalcY(self, context, y):
        return context.get_continuous_state_vector()


def test_python_continuous_state_integrates_like_cpp():
    builder = DiagramBuilder()
    source = builder.AddSystem(ConstantVectorSource(np.array([1.0, -2.0])))
    python_integrator = builder.AddSystem(PythonIntegrator(2))
    cpp_integrator = builder.AddSystem(Integrator(2))
    builder.Connect(source.get_output_port(0), python_integrator.get_input_port(0))
    builder.Connect(source.get_output_port(0), cpp_integrator.get_input_port(0))
    builder.ExportOutput(python_integrator.get_output_port(0), "python")
    builder.ExportOutput(cpp_integrator.get_output_port(0), "cpp")
    diagram = builder.Build()
    assert python_integrator.get_name() == "python_integrator"
    simulator = simulate(diagram, diagram.CreateDefaultContext(), 1.5)
    context = simulator.get_context()
    np.testing.assert_allclose(diagram.GetOutputPort("python").Eval(context), [1.5, -3.0], atol=1e-12)
    np.testing.assert_array_equal(diagram.GetOutputPort("python").Eval(context),
                                  diagram.GetOutputPort("cpp").Eval(context))


class Counter(LeafSystem):
    """Discrete state counting periodic updates, an abstract state of Python objects, and a publish log."""

    def __init__(self):
        super().__init__()
        self.DeclareDiscreteState(np.zeros(1))
        self.history = self.DeclareAbstractState({"ticks": []})
        self.DeclarePeriodicDiscreteUpdateEvent(0.1, 0.0, self.Tick)
        self.DeclarePeriodicUnrestrictedUpdateEvent(0.25, 0.0, self.Record)
        self.DeclareInitializationPublishEvent(self.OnStart)
        self.DeclareVectorOutputPort("count", 1, lambda context, y: context.get_discrete_state(0))
        self.DeclareAbstractOutputPort("history", {"ticks": []}, self.CalcHistory)
        self.publishes = []

    def Tick(self, context, discrete_state):
        discrete_state.get_value(0)[0] += 1.0

    def Record(self, context, state):
        history = state.get_mutable_abstract_state(self.history)
        history["ticks"].append(context.get_time())

    def OnStart(self, context):
        self.publishes.append(context.get_time())

    def CalcHistory(self, context, output):
        output.set_value(context.get_abstract_state(self.history))


def test_events_discrete_and_abstract_state():
    counter = Counter()
    context = counter.CreateDefaultContext()
    simulator = Simulator(counter, context)
    simulator.AdvanceTo(1.0)
    result = simulator.get_context()
    # Updates at t = 0, 0.1, ..., 1.0 (the simulator lands on 1.0 and applies updates due then at the next step).
    assert result.get_discrete_state(0)[0] == pytest.approx(10.0)
    assert result.get_abstract_state(counter.history)["ticks"] == pytest.approx([0.0, 0.25, 0.5, 0.75])
    assert counter.publishes == [0.0]
    assert counter.get_output_port(1).Eval(result)["ticks"] == pytest.approx([0.0, 0.25, 0.5, 0.75])
    # The original context was copied by the simulator, and copies of Python state are deep.
    assert context.get_abstract_state(counter.history) == {"ticks": []}
    clone = result.Clone()
    clone.get_mutable_abstract_state(counter.history)["ticks"].append(99.0)
    assert 99.0 not in result.get_abstract_state(counter.history)["ticks"]


class ObjectSource(LeafSystem):
    def __init__(self):
        super().__init__()
        self.DeclareAbstractOutputPort("out", AbstractValue.Make(None), lambda context, out: {"t": context.get_time()})


class ObjectSink(LeafSystem):
    def __init__(self):
        super().__init__()
        self.input = self.DeclareAbstractInputPort("in", AbstractValue.Make(None))
        self.seen = []
        self.DeclarePeriodicPublishEvent(0.1, 0.0, lambda context: self.seen.append(self.input.Eval(context)))


def test_python_objects_cross_cpp_abstract_systems():
    builder = DiagramBuilder()
    source = builder.AddSystem(ObjectSource())
    passthrough = builder.AddSystem(PassThrough(AbstractValue.Make(None)))
    sink = builder.AddSystem(ObjectSink())
    builder.Connect(source.get_output_port(0), passthrough.get_input_port(0))
    builder.Connect(passthrough.get_output_port(0), sink.get_input_port(0))
    diagram = builder.Build()
    simulator = Simulator(diagram)
    simulator.AdvanceTo(0.35)
    assert [value["t"] for value in sink.seen] == pytest.approx([0.0, 0.1, 0.2, 0.3])


def test_constant_value_source_and_fixed_inputs():
    source = ConstantValueSource(("a", 1))
    context = source.CreateDefaultContext()
    assert source.get_output_port(0).Eval(context) == ("a", 1)
    passthrough = PassThrough(3)
    pass_context = passthrough.CreateDefaultContext()
    passthrough.get_input_port(0).FixValue(pass_context, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(passthrough.get_output_port(0).Eval(pass_context), [1.0, 2.0, 3.0])
    function = FunctionSystem(2, 1, lambda t, u: [t + u[0] * u[1]])
    function_context = function.CreateDefaultContext()
    function_context.SetTime(0.5)
    function.get_input_port(0).FixValue(function_context, np.array([2.0, 3.0]))
    np.testing.assert_array_equal(function.get_output_port(0).Eval(function_context), [6.5])


def test_abstract_value_types():
    assert "Image" in AbstractValue.registered_types()
    assert "FootstepPlan" in AbstractValue.registered_types()
    value = AbstractValue.Make(np.arange(6, dtype=np.uint8).reshape(2, 3), type="Image")
    assert value.type_name() == "cv::Mat"
    np.testing.assert_array_equal(value.get_value(), [[0, 1, 2], [3, 4, 5]])
    with pytest.raises(ValueError, match="unknown type 'Imag'"):
        AbstractValue.Make(1, type="Imag")
    pose = AbstractValue.Make(np.eye(4), type="Isometry3d")
    np.testing.assert_array_equal(pose.get_value(), np.eye(4))
    with pytest.raises(ValueError, match="rigid transform"):
        AbstractValue.Make(2 * np.eye(4), type="Isometry3d")


def test_errors_carry_the_cpp_messages():
    builder = DiagramBuilder()
    gain = builder.AddSystem(Gain(1.0, 2))
    source = builder.AddSystem(ConstantVectorSource(np.zeros(3)))
    with pytest.raises(RuntimeError, match=r"\(vector of size 3\).*\(vector of size 2\): the ports carry different"):
        builder.Connect(source.get_output_port(0), gain.get_input_port(0))
    with pytest.raises(ValueError, match="already belongs"):
        DiagramBuilder().AddSystem(gain)
    with pytest.raises(RuntimeError, match="input ports with no source: 'gain_0.u'"):
        builder.Build()
    with pytest.raises(IndexError):
        gain.get_input_port(5)
    with pytest.raises(ValueError, match="closest|Did you mean|did you mean"):
        gain.GetInputPort("v")
    context = Gain(1.0, 2).CreateDefaultContext()
    with pytest.raises(RuntimeError, match="not created by|created by"):
        gain.get_output_port(0).Eval(context)
    with pytest.raises(TypeError, match="vector of size 2"):
        Gain(1.0, 2).get_input_port(0).FixValue(Gain(1.0, 2).CreateDefaultContext(), "text")
    with pytest.raises(TypeError, match="written in Python"):
        Gain(1.0, 2).DeclareVectorInputPort("u", 1)
    added = DiagramBuilder().AddSystem(PdControllerPy(1.0, 0.0, 0.0))
    with pytest.raises(RuntimeError, match="already belongs to a DiagramBuilder or Diagram: declare ports"):
        added.DeclareVectorInputPort("late", 1)


class Failing(LeafSystem):
    def __init__(self):
        super().__init__()
        self.DeclareVectorOutputPort("y", 1, self.Calc)

    def Calc(self, context, y):
        raise ZeroDivisionError("no output today")


def test_python_exceptions_keep_their_type_through_cpp():
    builder = DiagramBuilder()
    failing = builder.AddSystem(Failing())
    gain = builder.AddSystem(Gain(2.0, 1))
    builder.Connect(failing.get_output_port(0), gain.get_input_port(0))
    diagram = builder.Build()
    context = diagram.CreateDefaultContext()
    with pytest.raises(ZeroDivisionError, match="no output today"):
        gain.get_output_port(0).Eval(diagram.GetSubsystemContext(gain, context))


def test_monitor_stops_the_simulation():
    integrator = Integrator(np.array([0.0]))
    context = integrator.CreateDefaultContext()
    integrator.get_input_port(0).FixValue(context, [1.0])
    simulator = Simulator(integrator, context)
    simulator.set_monitor(lambda c: MonitorResult.Stop("far enough") if c.get_continuous_state_vector()[0] > 0.5
                          else None)
    status = simulator.AdvanceTo(2.0)
    assert not status.reached_boundary_time()
    assert status.message == "far enough"
    assert 0.5 < simulator.get_context().get_time() < 0.6


def test_ownership_keeps_python_systems_alive_and_cycles_collectable():
    def make():
        builder = DiagramBuilder()
        controller = builder.AddSystem(PdControllerPy(1.0, 0.1, 0.2))
        builder.ExportInput(controller.get_input_port(0), "state")
        builder.ExportOutput(controller.get_output_port(0), "torque")
        return builder.Build(), weakref.ref(controller)

    diagram, controller_ref = make()
    gc.collect()
    assert controller_ref() is not None  # the diagram keeps its Python system alive
    context = diagram.CreateDefaultContext()
    diagram.get_input_port(0).FixValue(context, [0.0, 0.0])
    np.testing.assert_allclose(diagram.get_output_port(0).Eval(context), [0.2])
    # A reference to a subsystem keeps the diagram alive.
    subsystem = diagram.GetSubsystemByName("pd_controller_py")
    diagram_ref = weakref.ref(diagram)
    del diagram, context
    gc.collect()
    assert diagram_ref() is not None
    assert subsystem.get_name() == "pd_controller_py"
    del subsystem
    gc.collect()
    # Dropping every reference frees the diagram and its Python systems (no leaked cycle).
    assert diagram_ref() is None
    assert controller_ref() is None


def test_vector_log_sink_records():
    builder = DiagramBuilder()
    source = builder.AddSystem(ConstantVectorSource(np.array([4.0])))
    sink = builder.AddSystem(VectorLogSink(1, 0.5))
    builder.Connect(source.get_output_port(0), sink.get_input_port(0))
    diagram = builder.Build()
    simulator = simulate(diagram, diagram.CreateDefaultContext(), 2.0)
    log = sink.GetLog(diagram.GetSubsystemContext(sink, simulator.get_context()))
    np.testing.assert_allclose(log.sample_times(), [0.0, 0.5, 1.0, 1.5, 2.0])
    assert copy.deepcopy(log.data().tolist()) == [[4.0] * 5]


def test_python_event_handlers_can_end_a_simulation():
    from cairn.systems import EventStatus, LeafSystem, Simulator, SimulatorStatus

    class Counter(LeafSystem):
        def __init__(self, how):
            super().__init__()
            self.how = how
            self.DeclareDiscreteState(np.zeros(1))
            self.DeclarePeriodicDiscreteUpdateEvent(0.1, 0.0, self.update)

        def update(self, context, next_state):
            values = next_state.get_value(0)
            values[0] += 1.0
            count = values[0]
            if count >= 3 and self.how == "stop":
                return EventStatus.ReachedTermination("counted to 3")
            if count >= 2 and self.how == "fail":
                return EventStatus.Failed("cannot count to 2")
            if self.how == "bad":
                return 42
            return None

    status = Simulator(Counter("stop")).AdvanceTo(10.0)
    assert status.reason == SimulatorStatus.Reason.kReachedTerminationCondition
    assert "counted to 3" in status.message
    assert status.time == pytest.approx(0.2)
    status = Simulator(Counter("fail")).AdvanceTo(10.0)
    assert status.reason == SimulatorStatus.Reason.kEventHandlerFailed
    assert "cannot count to 2" in status.message
    assert Simulator(Counter("none")).AdvanceTo(1.0).reached_boundary_time()
    with pytest.raises(TypeError, match="returned a int; return None or a cairn.systems.EventStatus"):
        Simulator(Counter("bad")).AdvanceTo(1.0)
