// Cairn's multibody algorithms against DART 6.12 in the same run, on Atlas (atlas_v3_no_head.urdf), DRC-Hubo and
// the project's humanoid, all with a floating base: forward kinematics, a frame Jacobian, gravity torques, inverse
// dynamics (RNEA), the mass matrix (CRBA) and forward dynamics; and Cairn's closed-form signed distances against
// FCL 0.7 (libccd). Figures are recorded in benchmarks/RESULTS.md.

#include <memory>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/distance.h>

#include <cairn/multibody/collision_world.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/dynamics.h>
#include <cairn/multibody/gravity_torques.h>
#include <cairn/multibody/jacobians.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/shape_distance.h>
#include <cairn/multibody/urdf_parser.h>

namespace {

using namespace cairn::multibody;

struct Robot {
  std::string name;
  std::string path;
  std::string package;  // package name to map, or empty
  std::string package_dir;
  std::string jacobian_body;  // a foot: the longest chain from the root
};

const std::vector<Robot>& Robots() {
  static const std::vector<Robot> robots = {
      {"Atlas", "/usr/share/doc/dart/data/sdf/atlas/atlas_v3_no_head.urdf", "", "", "l_foot"},
      {"DrcHubo", "/usr/share/doc/dart/data/urdf/drchubo/drchubo.urdf", "drchubo",
       "/usr/share/doc/dart/data/urdf/drchubo", "Body_LAR"},
      {"Humanoid", std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", "", "", "l_foot"},
  };
  return robots;
}

// Two random states per robot; benchmarks alternate between them so that no library can reuse a cached result.
struct States {
  Eigen::VectorXd q[2], v[2], a[2];
};

States MakeStates(const Model& model) {
  std::mt19937 rng(2026);
  std::normal_distribution<double> normal(0.0, 1.0);
  States s;
  for (int k = 0; k < 2; ++k) {
    s.q[k] = RandomConfiguration(model, rng, 1.0);
    s.v[k].resize(model.nv());
    s.a[k].resize(model.nv());
    for (int i = 0; i < model.nv(); ++i) s.v[k][i] = normal(rng);
    for (int i = 0; i < model.nv(); ++i) s.a[k][i] = normal(rng);
  }
  return s;
}

struct CairnRobot {
  explicit CairnRobot(const Robot& robot)
      : model(Load(robot)),
        data(model),
        states(MakeStates(model)),
        frame(model.GetFrameIndex(robot.jacobian_body)),
        J(6, model.nv()) {}
  static Model Load(const Robot& robot) {
    UrdfOptions options;
    options.floating_base = true;
    if (!robot.package.empty()) options.packages.Add(robot.package, robot.package_dir);
    return ParseUrdfFile(robot.path, options);
  }
  Model model;
  Data data;
  States states;
  int frame;
  Eigen::MatrixXd J;
};

struct DartRobot {
  DartRobot(const Robot& robot, const CairnRobot& cairn) {
    dart::utils::DartLoader loader;
    if (!robot.package.empty()) loader.addPackageDirectory(robot.package, robot.package_dir);
    skeleton = loader.parseSkeleton(dart::common::Uri::createFromPath(robot.path));
    body = skeleton->getBodyNode(robot.jacobian_body);
    // DART's own coordinates for the same states (free joint: rotation vector + translation).
    const int nv = cairn.model.nv();
    for (int k = 0; k < 2; ++k) {
      q[k].resize(nv);
      for (std::size_t i = 0; i < skeleton->getNumDofs(); ++i) {
        const dart::dynamics::Joint* joint = skeleton->getDof(i)->getJoint();
        if (joint->getNumDofs() == 6) continue;
        q[k][static_cast<Eigen::Index>(i)] =
            cairn.states.q[k][cairn.model.joint(cairn.model.GetJointIndex(joint->getName())).idx_q];
      }
      const Eigen::VectorXd& cq = cairn.states.q[k];
      Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
      X.translation() = cq.head<3>();
      X.linear() = Eigen::Quaterniond(cq[3], cq[4], cq[5], cq[6]).normalized().toRotationMatrix();
      q[k].head<6>() = dart::dynamics::FreeJoint::convertToPositions(X);
      v[k] = cairn.states.v[k];
      a[k] = cairn.states.a[k];
    }
  }
  dart::dynamics::SkeletonPtr skeleton;
  dart::dynamics::BodyNode* body = nullptr;
  Eigen::VectorXd q[2], v[2], a[2];
};

struct Pair {
  std::unique_ptr<CairnRobot> cairn;
  std::unique_ptr<DartRobot> dart;
};

Pair& Get(std::size_t robot) {
  static std::vector<Pair> pairs(Robots().size());
  Pair& pair = pairs[robot];
  if (!pair.cairn) {
    pair.cairn = std::make_unique<CairnRobot>(Robots()[robot]);
    pair.dart = std::make_unique<DartRobot>(Robots()[robot], *pair.cairn);
  }
  return pair;
}

enum class Op { kForwardKinematics, kFrameJacobian, kGravity, kRnea, kCrba, kForwardDynamics };
const char* OpName(Op op) {
  switch (op) {
    case Op::kForwardKinematics:
      return "ForwardKinematics";
    case Op::kFrameJacobian:
      return "FrameJacobian";
    case Op::kGravity:
      return "GravityTorques";
    case Op::kRnea:
      return "InverseDynamics";
    case Op::kCrba:
      return "MassMatrix";
    case Op::kForwardDynamics:
      return "ForwardDynamics";
  }
  return "?";
}

void BM_Cairn(benchmark::State& state, std::size_t robot, Op op) {
  CairnRobot& r = *Get(robot).cairn;
  const Eigen::VectorXd tau = Eigen::VectorXd::Constant(r.model.nv(), 1.0);
  int k = 0;
  for (auto _ : state) {
    const States& s = r.states;
    switch (op) {
      case Op::kForwardKinematics:
        ForwardKinematics(r.model, r.data, s.q[k]);
        benchmark::DoNotOptimize(r.data.X_world.back());
        break;
      case Op::kFrameJacobian:
        // Compared with DART's getWorldJacobian after setPositions, so the kinematics of the path is included.
        FrameJacobian(r.model, r.data, s.q[k], r.frame, ReferenceFrame::kWorld, r.J);
        benchmark::DoNotOptimize(r.J.data());
        break;
      case Op::kGravity:
        benchmark::DoNotOptimize(GravityTorques(r.model, r.data, s.q[k]).data());
        break;
      case Op::kRnea:
        benchmark::DoNotOptimize(InverseDynamics(r.model, r.data, s.q[k], s.v[k], s.a[k]).data());
        break;
      case Op::kCrba:
        benchmark::DoNotOptimize(MassMatrix(r.model, r.data, s.q[k]).data());
        break;
      case Op::kForwardDynamics:
        benchmark::DoNotOptimize(ForwardDynamics(r.model, r.data, s.q[k], s.v[k], tau).data());
        break;
    }
    benchmark::ClobberMemory();
    k ^= 1;
  }
}

void BM_Dart(benchmark::State& state, std::size_t robot, Op op) {
  DartRobot& r = *Get(robot).dart;
  dart::dynamics::Skeleton& skel = *r.skeleton;
  const Eigen::VectorXd tau = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(skel.getNumDofs()), 1.0);
  int k = 0;
  for (auto _ : state) {
    skel.setPositions(r.q[k]);
    switch (op) {
      case Op::kForwardKinematics:
        for (std::size_t b = 0; b < skel.getNumBodyNodes(); ++b) {
          benchmark::DoNotOptimize(skel.getBodyNode(b)->getWorldTransform().data());
        }
        break;
      case Op::kFrameJacobian:
        benchmark::DoNotOptimize(r.body->getWorldJacobian().data());
        break;
      case Op::kGravity:
        benchmark::DoNotOptimize(skel.getGravityForces().data());
        break;
      case Op::kRnea:
        skel.setVelocities(r.v[k]);
        skel.setAccelerations(r.a[k]);
        skel.computeInverseDynamics(false, false, false);
        benchmark::DoNotOptimize(skel.getForces().data());
        break;
      case Op::kCrba:
        benchmark::DoNotOptimize(skel.getMassMatrix().data());
        break;
      case Op::kForwardDynamics:
        skel.setVelocities(r.v[k]);
        skel.setForces(tau);
        skel.computeForwardDynamics();
        benchmark::DoNotOptimize(skel.getAccelerations().data());
        break;
    }
    benchmark::ClobberMemory();
    k ^= 1;
  }
}

// Signed distance of one primitive pair: Cairn's closed forms against FCL 0.7 with libccd (the FCL solver that
// gives true witness points and penetration depths). Box-sphere (+4.8 cm) and capsule-capsule (+0.6 cm) are
// near misses, box-box (-7.9 cm) and box-capsule (-4.9 cm) overlap: the cases a collision-avoiding optimiser meets.
enum class PairKind { kBoxSphere, kBoxBox, kCapsuleCapsule, kBoxCapsule };
const char* PairName(PairKind kind) {
  switch (kind) {
    case PairKind::kBoxSphere:
      return "BoxSphere";
    case PairKind::kBoxBox:
      return "BoxBox";
    case PairKind::kCapsuleCapsule:
      return "CapsuleCapsule";
    case PairKind::kBoxCapsule:
      return "BoxCapsule";
  }
  return "?";
}

const Pose kPoseA(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
                  Eigen::Vector3d(0.0, 0.0, 0.0));
const Pose kPoseB(Eigen::AngleAxisd(0.7, Eigen::Vector3d(-1, 1, 2).normalized()).toRotationMatrix(),
                  Eigen::Vector3d(0.25, 0.1, 0.3));
const Eigen::Vector3d kBoxSize(0.3, 0.2, 0.4);
constexpr double kRadius = 0.1;
constexpr double kLength = 0.3;

void BM_CairnPair(benchmark::State& state, PairKind kind) {
  const Eigen::Vector3d a = kPoseB * Eigen::Vector3d(0, 0, -0.5 * kLength);
  const Eigen::Vector3d b = kPoseB * Eigen::Vector3d(0, 0, 0.5 * kLength);
  const Eigen::Vector3d a2 = kPoseA * Eigen::Vector3d(0, 0, -0.5 * kLength);
  const Eigen::Vector3d b2 = kPoseA * Eigen::Vector3d(0, 0, 0.5 * kLength);
  for (auto _ : state) {
    ShapeDistance d;
    switch (kind) {
      case PairKind::kBoxSphere:
        d = BoxSphereDistance(kPoseA, kBoxSize, kPoseB.translation(), kRadius);
        break;
      case PairKind::kBoxBox:
        d = BoxBoxDistance(kPoseA, kBoxSize, kPoseB, kBoxSize);
        break;
      case PairKind::kCapsuleCapsule:
        d = CapsuleCapsuleDistance(a2, b2, kRadius, a, b, kRadius);
        break;
      case PairKind::kBoxCapsule:
        d = BoxCapsuleDistance(kPoseA, kBoxSize, a, b, kRadius);
        break;
    }
    benchmark::DoNotOptimize(d);
  }
}

void BM_FclPair(benchmark::State& state, PairKind kind) {
  std::shared_ptr<fcl::CollisionGeometryd> ga, gb;
  auto box = std::make_shared<fcl::Boxd>(kBoxSize);
  auto capsule = std::make_shared<fcl::Capsuled>(kRadius, kLength);
  switch (kind) {
    case PairKind::kBoxSphere:
      ga = box;
      gb = std::make_shared<fcl::Sphered>(kRadius);
      break;
    case PairKind::kBoxBox:
      ga = box;
      gb = box;
      break;
    case PairKind::kCapsuleCapsule:
      ga = capsule;
      gb = capsule;
      break;
    case PairKind::kBoxCapsule:
      ga = box;
      gb = capsule;
      break;
  }
  fcl::CollisionObjectd oa(ga, kPoseA.ToIsometry()), ob(gb, kPoseB.ToIsometry());
  fcl::DistanceRequestd request;
  request.enable_nearest_points = true;
  request.enable_signed_distance = true;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  for (auto _ : state) {
    fcl::DistanceResultd result;
    fcl::distance(&oa, &ob, request, result);
    benchmark::DoNotOptimize(result.min_distance);
  }
}

// All pairs of the humanoid (20 shapes) and a ground box closer than 5 cm, in a random posture.
void BM_CairnHumanoidPairsWithin(benchmark::State& state) {
  CairnRobot& r = *Get(2).cairn;
  CollisionWorld world(r.model);
  world.AddBox("ground", Eigen::Vector3d(4, 4, 0.1), Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -0.05)));
  Eigen::VectorXd q = NeutralConfiguration(r.model);
  q[2] = 0.87;
  ForwardKinematics(r.model, r.data, q);
  world.UpdatePoses(r.model, r.data);
  for (auto _ : state) {
    ForwardKinematics(r.model, r.data, q);
    world.UpdatePoses(r.model, r.data);
    benchmark::DoNotOptimize(world.PairsWithin(0.05));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Op ops[] = {Op::kForwardKinematics, Op::kFrameJacobian, Op::kGravity, Op::kRnea, Op::kCrba,
                    Op::kForwardDynamics};
  for (std::size_t robot = 0; robot < Robots().size(); ++robot) {
    for (const Op op : ops) {
      const std::string suffix = std::string(OpName(op)) + "/" + Robots()[robot].name;
      benchmark::RegisterBenchmark(("Cairn/" + suffix).c_str(), BM_Cairn, robot, op)->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("Dart/" + suffix).c_str(), BM_Dart, robot, op)->Unit(benchmark::kMicrosecond);
    }
  }
  for (const PairKind kind :
       {PairKind::kBoxSphere, PairKind::kBoxBox, PairKind::kCapsuleCapsule, PairKind::kBoxCapsule}) {
    benchmark::RegisterBenchmark((std::string("Cairn/SignedDistance/") + PairName(kind)).c_str(), BM_CairnPair, kind)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("Fcl/SignedDistance/") + PairName(kind)).c_str(), BM_FclPair, kind)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("Cairn/CollisionWorld/PairsWithin/Humanoid", BM_CairnHumanoidPairsWithin)
      ->Unit(benchmark::kMicrosecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
