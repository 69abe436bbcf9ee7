// Cairn::systems: integrates a constant through a diagram (source -> gain -> integrator) and a simulator.
#include <cmath>
#include <cstdio>

#include <cairn/systems/analysis/simulator.h>
#include <cairn/systems/framework/diagram_builder.h>
#include <cairn/systems/primitives/constant_vector_source.h>
#include <cairn/systems/primitives/gain.h>
#include <cairn/systems/primitives/integrator.h>

int main() {
  using namespace cairn::systems;
  DiagramBuilder builder;
  auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::VectorXd::Ones(1));
  auto* gain = builder.AddSystem<Gain>(2.0, 1);
  auto* integrator = builder.AddSystem<Integrator>(1);
  builder.Connect(*source, *gain);
  builder.Connect(*gain, *integrator);
  auto diagram = builder.Build();
  Simulator simulator(*diagram);
  simulator.AdvanceTo(1.0);
  const double x = simulator.get_context().get_continuous_state_vector()[0];
  std::printf("consumer systems: integrator reached %.6f after 1 s\n", x);
  return std::abs(x - 2.0) < 1e-9 ? 0 : 1;
}
