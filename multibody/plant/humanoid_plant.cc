#include <cairn/multibody/plant/humanoid_plant.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/plant/bullet_plant.h>
#include <cairn/multibody/plant/contact_monitor.h>
#include <cairn/systems/framework/context.h>
#include <cairn/systems/framework/state.h>
#include <cairn/systems/framework/value.h>

namespace cairn::multibody {

using systems::Context;
using systems::EventStatus;
using systems::State;

// The Bullet world and the monitor of one context, built at the first update.
struct HumanoidPlant::Engine {
  std::unique_ptr<BulletPlant> plant;
  std::unique_ptr<ContactMonitor> monitor;
  // The [q; v] this engine last wrote into the context: if the context holds anything else, it was set from
  // outside and the world is reset to it.
  Eigen::VectorXd last_state;
};

// Per-context storage must be copyable (contexts are cloned); a copy rebuilds the Bullet world at the source's
// state and copies the monitor, so two contexts never share a world.
class HumanoidPlant::EngineHandle {
 public:
  EngineHandle() = default;
  EngineHandle(const EngineHandle& other) { *this = other; }
  EngineHandle& operator=(const EngineHandle& other) {
    if (this == &other) return *this;
    engine.reset();
    if (other.engine) {
      const BulletPlant& source = *other.engine->plant;
      engine = std::make_unique<Engine>();
      engine->plant = std::make_unique<BulletPlant>(source.model(), source.terrain(), source.options());
      engine->plant->SetState(source.positions(), source.velocities());
      engine->monitor = std::make_unique<ContactMonitor>(*other.engine->monitor);
      engine->last_state = other.engine->last_state;
    }
    return *this;
  }
  std::unique_ptr<Engine> engine;
};

HumanoidPlant::HumanoidPlant(const Model& model, std::vector<TerrainBox> terrain, const JointPdController& controller,
                             const Eigen::VectorXd& initial_q, HumanoidPlantOptions options)
    : model_(model), terrain_(std::move(terrain)), controller_(controller), options_(std::move(options)) {
  if (model_.num_bodies() < 2 || model_.joint(1).type != JointType::kFloating) {
    throw std::invalid_argument("HumanoidPlant: model '" + model_.name() +
                                "' has no floating base; load the URDF with a floating base");
  }
  if (initial_q.size() != model_.nq() || !initial_q.allFinite()) {
    throw std::invalid_argument("HumanoidPlant: initial_q has size " + FormatShort(initial_q.size()) +
                                " or a non-finite entry; it needs " + FormatShort(model_.nq()) + " finite values");
  }
  if (controller_.kp().size() != model_.nv()) {
    throw std::invalid_argument("HumanoidPlant: the PD controller has " + FormatShort(controller_.kp().size()) +
                                " gains, but the model has " + FormatShort(model_.nv()) + " velocity coordinates");
  }
  // Build once here so that bad terrain, options or body names fail at construction, not in the first update.
  {
    BulletPlant probe(model_, terrain_, options_.bullet);
    ContactMonitor monitor(probe, options_.sole_bodies, options_.base_body, options_.drives, options_.monitor);
  }
  const int n = model_.nq() + model_.nv();
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(n);
  x0.head(model_.nq()) = initial_q;
  DeclareVectorInputPort("reference", n);
  if (options_.torque_input) torque_port_ = DeclareVectorInputPort("torque", model_.nv()).get_index();
  DeclareDiscreteState(x0);
  HumanoidMeasurements initial;
  initial.torque = Eigen::VectorXd::Zero(model_.nv());
  DeclareAbstractState(systems::Value<HumanoidMeasurements>(initial));
  engine_storage_ = DeclarePerContextStorage(systems::Value<EngineHandle>(EngineHandle()));
  DeclareStateOutputPort("state", 0);
  const Prerequisites measured = {abstract_state_ticket(0)};
  DeclareAbstractOutputPort(
      "contacts", systems::Value<std::vector<SoleState>>(initial.soles),
      [this](const Context& c, systems::AbstractValue* out) {
        out->get_mutable_value<std::vector<SoleState>>() = Measurements(c).soles;
      },
      measured);
  DeclareAbstractOutputPort(
      "slips", systems::Value<std::vector<SlipEvent>>(),
      [this](const Context& c, systems::AbstractValue* out) {
        out->get_mutable_value<std::vector<SlipEvent>>() = Measurements(c).slips;
      },
      measured);
  DeclareAbstractOutputPort(
      "stances", systems::Value<std::vector<StancePhase>>(),
      [this](const Context& c, systems::AbstractValue* out) {
        out->get_mutable_value<std::vector<StancePhase>>() = Measurements(c).stances;
      },
      measured);
  DeclareVectorOutputPort(
      "zmp", 3, [this](const Context& c, Eigen::VectorXd* y) { *y = Measurements(c).zmp; }, measured);
  DeclareVectorOutputPort(
      "energy", 3,
      [this](const Context& c, Eigen::VectorXd* y) {
        const HumanoidMeasurements& m = Measurements(c);
        *y << m.com_energy, m.electrical_energy, m.heat;
      },
      measured);
  DeclarePeriodicUnrestrictedUpdateEvent(options_.bullet.time_step, 0.0,
                                         [this](const Context& c, State* next) { return Update(c, next); });
}

HumanoidPlant::~HumanoidPlant() = default;

const HumanoidMeasurements& HumanoidPlant::Measurements(const Context& context) const {
  return context.get_abstract_state<HumanoidMeasurements>(0);
}

EventStatus HumanoidPlant::Update(const Context& context, State* next) const {
  const int nq = model_.nq();
  const int nv = model_.nv();
  const Eigen::VectorXd& x = context.get_discrete_state(0);
  EngineHandle& handle = GetMutablePerContextStorage<EngineHandle>(context, engine_storage_);
  if (!handle.engine) {
    handle.engine = std::make_unique<Engine>();
    handle.engine->plant = std::make_unique<BulletPlant>(model_, terrain_, options_.bullet);
    handle.engine->monitor = std::make_unique<ContactMonitor>(*handle.engine->plant, options_.sole_bodies,
                                                              options_.base_body, options_.drives, options_.monitor);
  }
  Engine& engine = *handle.engine;
  const bool same = engine.last_state.size() == x.size() &&
                    std::memcmp(engine.last_state.data(), x.data(), sizeof(double) * static_cast<std::size_t>(x.size())) == 0;
  if (!same) engine.plant->SetState(x.head(nq), x.tail(nv));

  const Eigen::VectorXd& reference = get_input_port(0).Eval<Eigen::VectorXd>(context);
  if (!reference.allFinite()) {
    return EventStatus::Failed("the reference [q; v] has a non-finite entry at t = " + FormatShort(context.get_time()));
  }
  Eigen::VectorXd feedforward = Eigen::VectorXd::Zero(nv);
  if (torque_port_ >= 0) feedforward = get_input_port(torque_port_).Eval<Eigen::VectorXd>(context);
  if (!feedforward.allFinite()) {
    return EventStatus::Failed("the torque input has a non-finite entry at t = " + FormatShort(context.get_time()));
  }
  const Eigen::VectorXd tau =
      controller_.Torques(x.head(nq), x.tail(nv), reference.head(nq), reference.tail(nv), feedforward);
  engine.plant->Step(tau);
  engine.monitor->Update(*engine.plant, tau);

  Eigen::VectorXd x_next(nq + nv);
  x_next << engine.plant->positions(), engine.plant->velocities();
  next->get_mutable_discrete_state().set_value(0, x_next);
  engine.last_state = x_next;

  const bool was_fallen = Measurements(context).fallen;
  HumanoidMeasurements& m = next->get_mutable_abstract_state<HumanoidMeasurements>(0);
  const ContactMonitor& monitor = *engine.monitor;
  m.soles = monitor.soles();
  if (m.slips.size() != monitor.slips().size()) m.slips = monitor.slips();
  m.stances = monitor.stances();
  m.zmp = monitor.zmp();
  m.com_energy = monitor.com_energy();
  m.electrical_energy = monitor.electrical_energy();
  m.heat = monitor.heat();
  m.fallen = monitor.fallen();
  m.fall_reason = monitor.fall_reason();
  m.torque = tau;
  if (m.fallen && !was_fallen && options_.stop_on_fall) {
    return EventStatus::ReachedTermination("the robot fell at t = " + FormatShort(monitor.fall_time()) + " s: " +
                                           m.fall_reason);
  }
  return EventStatus::Succeeded();
}

}  // namespace cairn::multibody
