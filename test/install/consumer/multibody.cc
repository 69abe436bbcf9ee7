// Cairn::multibody: loads the project's humanoid URDF (data/robots) and computes its centre of mass; moving the
// floating base 1 m along x must move the COM by exactly that.
#include <cmath>
#include <cstdio>

#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/urdf_parser.h>

int main() {
  using namespace cairn::multibody;
  UrdfOptions options;
  options.floating_base = true;
  const Model model = ParseUrdfFile(CAIRN_HUMANOID_URDF, options);
  Data data(model);
  Eigen::VectorXd q = NeutralConfiguration(model);
  const Eigen::Vector3d com = CenterOfMass(model, data, q);
  q[0] += 1.0;  // the floating joint's x
  const Eigen::Vector3d moved = CenterOfMass(model, data, q);
  std::printf("consumer multibody: %d bodies, %.3f kg, COM (%.4f, %.4f, %.4f) m\n", model.num_bodies(),
              model.total_mass(), com.x(), com.y(), com.z());
  const bool right = model.total_mass() > 0.0 && com.allFinite() &&
                     (moved - com - Eigen::Vector3d::UnitX()).norm() < 1e-12;
  return right ? 0 : 1;
}
