// Cairn::multibody_plant: the humanoid in Bullet without contacts falls freely; after 0.1 s its base must have
// dropped by g t^2 / 2 (semi-implicit Euler at 1 ms: g t (t + h) / 2).
#include <cmath>
#include <cstdio>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/plant/bullet_plant.h>
#include <cairn/multibody/urdf_parser.h>

int main() {
  using namespace cairn::multibody;
  UrdfOptions urdf;
  urdf.floating_base = true;
  const Model model = ParseUrdfFile(CAIRN_HUMANOID_URDF, urdf);
  BulletPlantOptions options;
  options.contacts = false;
  BulletPlant plant(model, {}, options);
  plant.SetState(NeutralConfiguration(model), Eigen::VectorXd::Zero(model.nv()));
  const double z0 = plant.positions()[2];
  for (int i = 0; i < 100; ++i) plant.Step(Eigen::VectorXd::Zero(model.nv()));
  const double drop = z0 - plant.positions()[2];
  const double expected = 0.5 * 9.81 * 0.1 * (0.1 + 1e-3);
  std::printf("consumer multibody_plant: %d links, dropped %.6f m in %.3f s (expected %.6f m)\n", plant.num_links(),
              drop, plant.time(), expected);
  return std::abs(drop - expected) < 1e-9 ? 0 : 1;
}
