// Cairn::visualization: a page showing the humanoid standing on one box, with three.js inlined.
#include <cstdio>
#include <string>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/visualization/motion_html.h>

int main() {
  cairn::multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const cairn::multibody::Model model = cairn::multibody::ParseUrdfFile(CAIRN_HUMANOID_URDF, urdf);
  cairn::visualization::MotionScene scene;
  scene.title = "standing";
  Eigen::VectorXd q = cairn::multibody::NeutralConfiguration(model);
  q[2] = 0.9;
  scene.times = {0.0, 1.0};
  scene.q = {q, q};
  cairn::visualization::SceneBox ground;
  ground.name = "ground";
  ground.size = Eigen::Vector3d(4.0, 4.0, 1.0);
  ground.X_WB = cairn::multibody::Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.5));
  scene.boxes.push_back(ground);
  const std::string html = cairn::visualization::MotionHtml(model, scene);
  // Inlined, not linked: three.js's own code contains "src=" (image loaders), so look for a script tag's.
  const bool inlined = html.find("THREE") != std::string::npos && html.find("<script src") == std::string::npos;
  std::printf("consumer visualization: %zu bytes of HTML, three.js %s\n", html.size(), inlined ? "inlined" : "MISSING");
  return inlined ? 0 : 1;
}
