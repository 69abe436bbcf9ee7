// MotionHtml: the page's content and its errors, and the page itself in headless Chromium (it loads without a
// script error and draws something).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/visualization/motion_html.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::visualization {
namespace {

namespace fs = std::filesystem;

const multibody::Model& Humanoid() {
  static const multibody::Model model = [] {
    multibody::UrdfOptions urdf;
    urdf.floating_base = true;
    return multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", urdf);
  }();
  return model;
}

// The humanoid standing and then stepping 0.2 m forward over 1 s, on ground with an ice patch, beside a cell that
// perception found occupied with probability 0.7.
MotionScene Scene() {
  MotionScene scene;
  scene.title = "test scene";
  for (int k = 0; k <= 25; ++k) {
    Eigen::VectorXd q = multibody::NeutralConfiguration(Humanoid());
    q[0] = 0.2 * k / 25.0;
    q[2] = 0.9;
    scene.times.push_back(0.04 * k);
    scene.q.push_back(q);
  }
  SceneBox ground{"ground", multibody::Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0.0, -0.5)),
                  Eigen::Vector3d(3.0, 2.0, 1.0), 1.0};
  SceneBox ice{"ice", multibody::Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, -0.499)),
               Eigen::Vector3d(0.5, 0.5, 1.0), 0.06};
  SceneBox cell{"occupied", multibody::Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.6, 0.4, 0.3)),
                Eigen::Vector3d(0.05, 0.05, 0.05), 1.0, 0.7};
  scene.boxes = {ground, ice, cell};
  return scene;
}

TEST(MotionHtmlTest, InlinesThreeJsAndEmbedsOnePoseOfEveryShapePerFrame) {
  const std::string html = MotionHtml(Humanoid(), Scene());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(html.find("<script src"), std::string::npos);  // nothing fetched: it works offline
  EXPECT_NE(html.find("WebGLRenderer"), std::string::npos);
  EXPECT_NE(html.find("\"title\": \"test scene\""), std::string::npos);
  EXPECT_NE(html.find("\"name\": \"ice\", \"friction\": 0.0600, \"size\""), std::string::npos);
  EXPECT_NE(html.find("\"name\": \"occupied\", \"friction\": 1.0000, \"occupancy\": 0.7000"), std::string::npos);
  int shapes = 0;
  for (const multibody::Body& body : Humanoid().bodies()) {
    for (const multibody::Geometry& g : body.collisions) shapes += g.type != multibody::GeometryType::kMesh;
  }
  ASSERT_GT(shapes, 0);
  // 26 frames of `shapes` poses; each pose is an array of 7 numbers: count the pose arrays' openings in "frames".
  const std::size_t frames = html.find("\"frames\": [");
  const std::size_t end = html.find("\"centre\"", frames);
  ASSERT_NE(frames, std::string::npos);
  std::size_t brackets = 0;
  for (std::size_t i = frames + 11; i < end; ++i) brackets += html[i] == '[';
  EXPECT_EQ(brackets, 26u * (static_cast<std::size_t>(shapes) + 1));
}

TEST(MotionHtmlTest, RefusesABadSceneWithAMessage) {
  MotionScene scene = Scene();
  scene.times.pop_back();
  CAIRN_EXPECT_THROWS_WITH(MotionHtml(Humanoid(), scene), std::invalid_argument,
                           "25 times but 26 configurations");
  scene = Scene();
  scene.q[3].resize(4);
  CAIRN_EXPECT_THROWS_WITH(MotionHtml(Humanoid(), scene), std::invalid_argument, "configuration 3 has size 4");
  scene = Scene();
  scene.times[5] = 0.0;
  CAIRN_EXPECT_THROWS_WITH(MotionHtml(Humanoid(), scene), std::invalid_argument,
                           "comes before the previous frame's");
  scene = Scene();
  scene.boxes[1].size.z() = 0.0;
  CAIRN_EXPECT_THROWS_WITH(MotionHtml(Humanoid(), scene), std::invalid_argument, "box 'ice' has a side");
  scene = Scene();
  scene.boxes[2].occupancy = 1.5;
  CAIRN_EXPECT_THROWS_WITH(MotionHtml(Humanoid(), scene), std::invalid_argument,
                           "box 'occupied' has occupancy 1.5; give a probability in [0, 1]");
  CAIRN_EXPECT_THROWS_WITH(MotionHtml(Humanoid(), Scene(), "/nonexistent/three.min.js"), std::runtime_error,
                           "cannot read three.js from '/nonexistent/three.min.js'; install Debian's libjs-three");
}

std::string RunCommand(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>/dev/null").c_str(), "r");
  if (pipe == nullptr) return output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) output += buffer;
  ::pclose(pipe);
  return output;
}

TEST(MotionHtmlTest, LoadsWithoutAScriptErrorAndDrawsInHeadlessChromium) {
  const char* chromium = "/usr/bin/chromium";
  // scripts/install_deps.sh installs Chromium, so the suite's own run has it; a missing browser is a failure there,
  // not a quiet skip.
  if (!fs::exists(chromium)) {
    FAIL() << "no /usr/bin/chromium: install it (scripts/install_deps.sh) to check the page in a browser";
  }
  const fs::path dir = fs::temp_directory_path() / ("cairn_motion_html_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path page = dir / "motion.html";
  std::ofstream(page) << MotionHtml(Humanoid(), Scene());
  // Software WebGL (SwiftShader): no GPU in a headless test; a profile of its own, so runs do not share state.
  const std::string flags = std::string(chromium) + " --headless --no-sandbox --disable-gpu-sandbox "
                            "--use-angle=swiftshader --enable-unsafe-swiftshader --window-size=800,600 "
                            "--user-data-dir=" + (dir / "profile").string() + " --virtual-time-budget=3000 ";
  const std::string dom = RunCommand(flags + "--dump-dom file://" + page.string());
  EXPECT_NE(dom.find("data-status=\"rendered\""), std::string::npos)
      << "the page did not finish drawing: " << dom.substr(0, dom.find("<div"));
  const fs::path png = dir / "shot.png";
  RunCommand(flags + "--screenshot=" + png.string() + " file://" + page.string());
  const cv::Mat image = cv::imread(png.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty()) << "no screenshot at " << png;
  // Pixels far from the clear colour (#f4f6f8): terrain, robot, slider and text.
  int drawn = 0;
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      const cv::Vec3b p = image.at<cv::Vec3b>(r, c);
      drawn += std::abs(p[0] - 0xf8) + std::abs(p[1] - 0xf6) + std::abs(p[2] - 0xf4) > 60;
    }
  }
  EXPECT_GT(drawn, image.rows * image.cols / 20) << "the screenshot is almost blank: " << drawn << " pixels drawn";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cairn::visualization
