#include <cairn/visualization/motion_html.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>

#include <cairn/common/json_writer.h>
#include <cairn/common/number_text.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::visualization {
namespace {

// A pose as [x, y, z, qw, qx, qy, qz].
void WritePose(JsonWriter& json, const multibody::Pose& X) {
  const Eigen::Quaterniond r(X.rotation());
  const JsonWriter::NumberFormat f = JsonWriter::Fixed(4);
  json.BeginArray();
  for (int i = 0; i < 3; ++i) json.Number(X.translation()[i], f);
  json.Number(r.w(), f).Number(r.x(), f).Number(r.y(), f).Number(r.z(), f).EndArray();
}

std::string ReadThreeJs(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in || text.str().empty()) {
    throw std::runtime_error("MotionHtml: cannot read three.js from '" + path +
                             "'; install Debian's libjs-three (scripts/install_deps.sh)");
  }
  // The script is inlined: a literal "</script" inside it would end the element early.
  std::string js = text.str();
  for (std::size_t at = js.find("</script"); at != std::string::npos; at = js.find("</script", at + 2)) {
    js.replace(at, 2, "<\\/");
  }
  return js;
}

// The page's own script: builds the scene from the embedded JSON and plays it.
constexpr const char* kViewerScript = R"JS(
(function () {
  const status = (s) => document.body.setAttribute('data-status', s);
  window.addEventListener('error', (e) => status('error: ' + e.message));
  const scene_data = JSON.parse(document.getElementById('motion').textContent);
  document.getElementById('title').textContent = scene_data.title;
  const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const view = document.getElementById('view');
  renderer.setSize(view.clientWidth, view.clientHeight);
  renderer.setClearColor(0xf4f6f8);
  view.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  const sun = new THREE.DirectionalLight(0xffffff, 0.75);
  sun.position.set(2, -3, 5);
  scene.add(sun);
  const setPose = (object, p) => {
    object.position.set(p[0], p[1], p[2]);
    object.quaternion.set(p[4], p[5], p[6], p[3]);
  };
  // Terrain: red for mu = 0 to green for mu >= 1.
  // Occupied cells of perception: dark red, as opaque as they are probable.
  for (const box of scene_data.boxes) {
    const mu = Math.max(0, Math.min(1, box.friction));
    const material = box.occupancy === undefined
        ? new THREE.MeshLambertMaterial({color: new THREE.Color().setHSL(0.33 * mu, 0.55, 0.6)})
        : new THREE.MeshLambertMaterial({color: 0x8b1a1a, transparent: true, opacity: 0.15 + 0.7 * box.occupancy,
                                         depthWrite: false});
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(box.size[0], box.size[1], box.size[2]), material);
    setPose(mesh, box.pose);
    scene.add(mesh);
  }
  const robot_material = new THREE.MeshLambertMaterial({color: 0x4a78b5});
  const shapes = [];
  for (const shape of scene_data.shapes) {
    let object;
    if (shape.type === 'box') {
      object = new THREE.Mesh(new THREE.BoxGeometry(shape.size[0], shape.size[1], shape.size[2]), robot_material);
    } else if (shape.type === 'sphere') {
      object = new THREE.Mesh(new THREE.SphereGeometry(shape.radius, 16, 12), robot_material);
    } else {
      // Cylinders and capsules: three.js builds them along y, the geometry frame's axis is z.
      object = new THREE.Group();
      const body = new THREE.Mesh(new THREE.CylinderGeometry(shape.radius, shape.radius, shape.length, 16),
                                  robot_material);
      body.rotation.x = Math.PI / 2;
      object.add(body);
      if (shape.type === 'capsule') {
        for (const side of [-1, 1]) {
          const cap = new THREE.Mesh(new THREE.SphereGeometry(shape.radius, 16, 12), robot_material);
          cap.position.z = side * shape.length / 2;
          object.add(cap);
        }
      }
    }
    scene.add(object);
    shapes.push(object);
  }
  // Camera orbiting the robot's start, z up; drag to turn, wheel to zoom.
  const camera = new THREE.PerspectiveCamera(45, view.clientWidth / view.clientHeight, 0.01, 200);
  camera.up.set(0, 0, 1);
  const target = new THREE.Vector3(scene_data.centre[0], scene_data.centre[1], scene_data.centre[2]);
  let azimuth = -1.2, elevation = 0.35, distance = scene_data.radius;
  const placeCamera = () => {
    camera.position.set(target.x + distance * Math.cos(elevation) * Math.cos(azimuth),
                        target.y + distance * Math.cos(elevation) * Math.sin(azimuth),
                        target.z + distance * Math.sin(elevation));
    camera.lookAt(target);
  };
  let dragging = null;
  renderer.domElement.addEventListener('mousedown', (e) => { dragging = [e.clientX, e.clientY]; });
  window.addEventListener('mouseup', () => { dragging = null; });
  window.addEventListener('mousemove', (e) => {
    if (!dragging) return;
    azimuth -= 0.01 * (e.clientX - dragging[0]);
    elevation = Math.max(-1.4, Math.min(1.4, elevation + 0.01 * (e.clientY - dragging[1])));
    dragging = [e.clientX, e.clientY];
    draw();
  });
  renderer.domElement.addEventListener('wheel', (e) => {
    distance = Math.max(0.3, Math.min(100, distance * (e.deltaY > 0 ? 1.1 : 0.9)));
    e.preventDefault();
    draw();
  });
  const slider = document.getElementById('time');
  const label = document.getElementById('label');
  slider.max = Math.max(0, scene_data.times.length - 1);
  let frame = 0;
  const draw = () => {
    const poses = scene_data.frames[frame] || [];
    for (let i = 0; i < shapes.length && i < poses.length; ++i) setPose(shapes[i], poses[i]);
    label.textContent = 't = ' + (scene_data.times[frame] || 0).toFixed(2) + ' s of ' +
                        (scene_data.times[scene_data.times.length - 1] || 0).toFixed(2) + ' s';
    placeCamera();
    renderer.render(scene, camera);
  };
  slider.addEventListener('input', () => { frame = Number(slider.value); draw(); });
  let playing = null;
  const play = document.getElementById('play');
  play.addEventListener('click', () => {
    if (playing) { clearInterval(playing); playing = null; play.textContent = 'play'; return; }
    play.textContent = 'pause';
    const start = performance.now() - 1000 * (scene_data.times[frame] || 0);
    playing = setInterval(() => {
      const t = (performance.now() - start) / 1000;
      while (frame + 1 < scene_data.times.length && scene_data.times[frame + 1] <= t) ++frame;
      slider.value = frame;
      draw();
      if (frame + 1 >= scene_data.times.length) { clearInterval(playing); playing = null; play.textContent = 'play'; }
    }, 20);
  });
  window.addEventListener('resize', () => {
    renderer.setSize(view.clientWidth, view.clientHeight);
    camera.aspect = view.clientWidth / view.clientHeight;
    camera.updateProjectionMatrix();
    draw();
  });
  draw();
  status('rendered');
})();
)JS";

}  // namespace

std::string DefaultThreeJsPath() { return CAIRN_THREE_JS_PATH; }

std::string MotionHtml(const multibody::Model& model, const MotionScene& scene, const std::string& three_js_path) {
  if (scene.times.size() != scene.q.size()) {
    throw std::invalid_argument("MotionHtml: " + FormatShort(scene.times.size()) + " times but " +
                                FormatShort(scene.q.size()) + " configurations; give one time per configuration");
  }
  if (scene.q.size() > kMaxMotionFrames) {
    throw std::invalid_argument("MotionHtml: " + FormatShort(scene.q.size()) + " frames, more than the limit of " +
                                FormatShort(kMaxMotionFrames) + "; subsample the motion");
  }
  if (scene.boxes.size() > kMaxSceneBoxes) {
    throw std::invalid_argument("MotionHtml: " + FormatShort(scene.boxes.size()) + " boxes, more than the limit of " +
                                FormatShort(kMaxSceneBoxes));
  }
  for (std::size_t k = 0; k < scene.q.size(); ++k) {
    if (scene.q[k].size() != model.nq() || !scene.q[k].allFinite()) {
      throw std::invalid_argument("MotionHtml: configuration " + FormatShort(k) + " has size " +
                                  FormatShort(scene.q[k].size()) + " or is not finite; model '" + model.name() +
                                  "' needs " + FormatShort(model.nq()) + " finite coordinates");
    }
    if (!std::isfinite(scene.times[k]) || (k > 0 && scene.times[k] < scene.times[k - 1])) {
      throw std::invalid_argument("MotionHtml: time " + FormatShort(scene.times[k]) + " s of frame " + FormatShort(k) +
                                  " is not finite or comes before the previous frame's");
    }
  }
  for (const SceneBox& box : scene.boxes) {
    if (!(box.size.minCoeff() > 0.0) || !box.size.allFinite() || !box.X_WB.translation().allFinite()) {
      throw std::invalid_argument("MotionHtml: box '" + box.name + "' has a side that is not positive and finite");
    }
    if (!(box.occupancy <= 1.0)) {
      throw std::invalid_argument("MotionHtml: box '" + box.name + "' has occupancy " + FormatShort(box.occupancy) +
                                  "; give a probability in [0, 1], or a negative value for a terrain box");
    }
  }
  const std::string three = ReadThreeJs(three_js_path);

  // The drawable collision shapes, in body order.
  struct Shape {
    int body;
    const multibody::Geometry* geometry;
  };
  std::vector<Shape> shapes;
  for (int b = 0; b < model.num_bodies(); ++b) {
    for (const multibody::Geometry& g : model.body(b).collisions) {
      if (g.type != multibody::GeometryType::kMesh) shapes.push_back({b, &g});
    }
  }
  JsonWriter json;
  const JsonWriter::NumberFormat f4 = JsonWriter::Fixed(4);
  json.BeginObject().Key("title").String(scene.title).Key("shapes").BeginArray();
  for (const Shape& s : shapes) {
    const multibody::Geometry& g = *s.geometry;
    json.BeginObject().Key("body").String(model.body(s.body).name).Key("type").String(multibody::GeometryTypeName(g.type));
    json.Key("size").BeginArray().Number(g.size.x(), f4).Number(g.size.y(), f4).Number(g.size.z(), f4).EndArray();
    json.Key("radius").Number(g.radius, f4).Key("length").Number(g.length, f4).EndObject();
  }
  json.EndArray().Key("boxes").BeginArray();
  for (const SceneBox& box : scene.boxes) {
    json.BeginObject().Key("name").String(box.name).Key("friction").Number(box.friction, f4);
    if (box.occupancy >= 0.0) json.Key("occupancy").Number(box.occupancy, f4);
    json.Key("size").BeginArray();
    for (int i = 0; i < 3; ++i) json.Number(box.size[i], f4);
    json.EndArray().Key("pose");
    WritePose(json, box.X_WB);
    json.EndObject();
  }
  json.EndArray().Key("times").BeginArray();
  for (double t : scene.times) json.Number(t, JsonWriter::Fixed(3));
  json.EndArray().Key("frames").BeginArray();
  multibody::Data data(model);
  Eigen::Vector3d centre = Eigen::Vector3d(0.0, 0.0, 0.8);
  double radius = 4.0;
  for (std::size_t k = 0; k < scene.q.size(); ++k) {
    multibody::ForwardKinematics(model, data, scene.q[k]);
    if (k == 0 && model.num_bodies() > 1) {
      centre = data.X_world[1].translation();
      if (!scene.q.empty()) {
        multibody::Data last(model);
        multibody::ForwardKinematics(model, last, scene.q.back());
        centre = 0.5 * (centre + last.X_world[1].translation());
        radius = std::max(3.0, 1.5 * (last.X_world[1].translation() - data.X_world[1].translation()).norm() + 2.5);
      }
    }
    json.BreakLine(0).BeginArray();
    for (const Shape& s : shapes) WritePose(json, data.X_world[static_cast<std::size_t>(s.body)] * s.geometry->X_BG);
    json.EndArray();
  }
  json.EndArray().Key("centre").BeginArray().Number(centre.x(), f4).Number(centre.y(), f4).Number(centre.z(), f4);
  json.EndArray().Key("radius").Number(radius, f4).EndObject();
  std::string motion = json.text();
  for (std::size_t at = motion.find("</"); at != std::string::npos; at = motion.find("</", at + 2)) {
    motion.replace(at, 2, "<\\/");
  }

  std::string html;
  html.reserve(three.size() + motion.size() + 8192);
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  html += "Cairn motion viewer</title>\n<style>\nhtml, body { margin: 0; height: 100%; font: 14px sans-serif; }\n"
          "#bar { position: absolute; left: 0; right: 0; bottom: 0; padding: 8px 12px; background: #ffffffd0; "
          "display: flex; gap: 12px; align-items: center; }\n#time { flex: 1; }\n#view { position: absolute; top: 0; "
          "left: 0; right: 0; bottom: 44px; }\n#title { position: absolute; top: 8px; left: 12px; z-index: 1; }\n"
          "#legend { position: absolute; top: 8px; right: 12px; z-index: 1; background: #ffffffd0; padding: 4px; }\n"
          "</style>\n</head>\n<body data-status=\"loading\">\n<div id=\"title\"></div>\n"
          "<div id=\"legend\">terrain friction: <span style=\"color:hsl(0,55%,50%)\">&#9632; 0</span> "
          "<span style=\"color:hsl(60,55%,50%)\">&#9632; 0.5</span> "
          "<span style=\"color:hsl(120,55%,45%)\">&#9632; &ge; 1</span>; <span style=\"color:#8b1a1a\">&#9632;</span> "
          "occupied (opacity: probability); robot: collision shapes</div>\n"
          "<div id=\"view\"></div>\n<div id=\"bar\"><button id=\"play\">play</button>"
          "<input id=\"time\" type=\"range\" min=\"0\" max=\"0\" value=\"0\" step=\"1\" aria-label=\"time\">"
          "<span id=\"label\"></span></div>\n<script id=\"motion\" type=\"application/json\">";
  html += motion;
  html += "</script>\n<script>\n";
  html += three;
  html += "\n</script>\n<script>";
  html += kViewerScript;
  html += "</script>\n</body>\n</html>\n";
  return html;
}

}  // namespace cairn::visualization
