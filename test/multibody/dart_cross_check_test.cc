// Cross-checks Cairn's kinematics and dynamics against DART 6.12 (an independent implementation) on Atlas and
// DRC-Hubo: link poses, mass matrix, gravity forces, inverse and forward dynamics at random states.

#include <map>
#include <random>
#include <string>
#include <vector>

#include <dart/dynamics/DegreeOfFreedom.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/utils/urdf/DartLoader.hpp>
#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/dynamics.h>
#include <cairn/multibody/gravity_torques.h>
#include <cairn/multibody/kinematics.h>

#include "test_models.h"

namespace cairn::multibody {
namespace {

using test::DrcHuboPackageDir;
using test::DrcHuboUrdf;

// One robot loaded into both libraries, with the map from DART's dof order to Cairn's velocity indices.
struct Pair {
  Model model;
  dart::dynamics::SkeletonPtr skeleton;
  std::vector<int> dof_to_v;  // DART dof index -> Cairn velocity index
};

Pair Load(const std::string& path, bool floating) {
  Pair pair{test::LoadRobot(path, floating), nullptr, {}};
  dart::utils::DartLoader::Options options;
  options.mDefaultRootJointType =
      floating ? dart::utils::DartLoader::RootJointType::FLOATING : dart::utils::DartLoader::RootJointType::FIXED;
  // DART gives links without <inertial> 1 kg; Cairn reads them as massless. Compare like with like.
  options.mDefaultInertia = dart::dynamics::Inertia(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  dart::utils::DartLoader loader(options);
  if (path == DrcHuboUrdf()) loader.addPackageDirectory("drchubo", DrcHuboPackageDir());
  pair.skeleton = loader.parseSkeleton(dart::common::Uri::createFromPath(path));
  EXPECT_NE(pair.skeleton, nullptr);
  for (std::size_t i = 0; i < pair.skeleton->getNumDofs(); ++i) {
    const dart::dynamics::DegreeOfFreedom* dof = pair.skeleton->getDof(i);
    const dart::dynamics::Joint* joint = dof->getJoint();
    if (joint->getNumDofs() == 6) {
      const int root = pair.model.GetJointIndex("root_joint");
      pair.dof_to_v.push_back(pair.model.joint(root).idx_v + static_cast<int>(dof->getIndexInJoint()));
    } else {
      pair.dof_to_v.push_back(pair.model.joint(pair.model.GetJointIndex(joint->getName())).idx_v);
    }
  }
  return pair;
}

// Sets DART's state to Cairn's (q, v).
void SetState(const Pair& pair, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const int nv = pair.model.nv();
  Eigen::VectorXd positions(nv), velocities(nv);
  for (int i = 0; i < nv; ++i) velocities[i] = v[pair.dof_to_v[static_cast<std::size_t>(i)]];
  for (std::size_t i = 0; i < pair.skeleton->getNumDofs(); ++i) {
    const dart::dynamics::Joint* joint = pair.skeleton->getDof(i)->getJoint();
    if (joint->getNumDofs() == 6) continue;
    const Joint& cj = pair.model.joint(pair.model.GetJointIndex(joint->getName()));
    positions[static_cast<Eigen::Index>(i)] = q[cj.idx_q];
  }
  if (pair.model.HasJoint("root_joint")) {
    const Joint& root = pair.model.joint(pair.model.GetJointIndex("root_joint"));
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.translation() = q.segment<3>(root.idx_q);
    X.linear() = Eigen::Quaterniond(q[root.idx_q + 3], q[root.idx_q + 4], q[root.idx_q + 5], q[root.idx_q + 6])
                     .normalized()
                     .toRotationMatrix();
    // DART's free joint is the first dof block; its positions are (rotation vector, translation).
    positions.head<6>() = dart::dynamics::FreeJoint::convertToPositions(X);
  }
  pair.skeleton->setPositions(positions);
  pair.skeleton->setVelocities(velocities);
}

// Reads one value per dof. DART's by-value vector getters (getForces, getAccelerations) hand over Eigen storage
// allocated inside libdart; under AddressSanitizer Eigen frees it with its own aligned allocator, which does not
// match, so the tests read dofs one by one instead.
Eigen::VectorXd DofValues(const dart::dynamics::Skeleton& skeleton,
                          double (dart::dynamics::DegreeOfFreedom::*getter)() const) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(skeleton.getNumDofs()));
  for (std::size_t i = 0; i < skeleton.getNumDofs(); ++i)
    out[static_cast<Eigen::Index>(i)] = (skeleton.getDof(i)->*getter)();
  return out;
}

// Relative comparison with an absolute floor for entries that are zero in exact arithmetic.
void ExpectNear(const Eigen::MatrixXd& expected, const Eigen::MatrixXd& actual, double rel, const std::string& what) {
  ASSERT_EQ(expected.rows(), actual.rows()) << what;
  ASSERT_EQ(expected.cols(), actual.cols()) << what;
  const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
  EXPECT_LE((expected - actual).cwiseAbs().maxCoeff(), rel * scale) << what;
}

class DartCrossCheckTest : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(DartCrossCheckTest, PosesMassMatrixGravityInverseAndForwardDynamicsAgree) {
  const auto& [path, floating] = GetParam();
  const Pair pair = Load(path, floating);
  const Model& model = pair.model;
  ASSERT_EQ(static_cast<int>(pair.skeleton->getNumDofs()), model.nv());
  EXPECT_NEAR(pair.skeleton->getMass(), model.total_mass(), 1e-9 * model.total_mass());
  Data data(model);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int nv = model.nv();
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd q = RandomConfiguration(model, rng, 1.0);
    Eigen::VectorXd v(nv), a(nv);
    for (int i = 0; i < nv; ++i) v[i] = uniform(rng);
    for (int i = 0; i < nv; ++i) a[i] = uniform(rng);
    SetState(pair, q, v);

    ForwardKinematics(model, data, q);
    for (std::size_t b = 0; b < pair.skeleton->getNumBodyNodes(); ++b) {
      const dart::dynamics::BodyNode* node = pair.skeleton->getBodyNode(b);
      const Pose expected(node->getWorldTransform());
      const Pose& actual = data.X_world[static_cast<std::size_t>(model.GetBodyIndex(node->getName()))];
      EXPECT_TRUE(actual.IsApprox(expected, 1e-9)) << node->getName() << " trial " << trial;
    }

    // Permutation: Cairn quantity indexed through DART's dof order.
    auto permute_vector = [&](const Eigen::VectorXd& x) {
      Eigen::VectorXd out(nv);
      for (int i = 0; i < nv; ++i) out[i] = x[pair.dof_to_v[static_cast<std::size_t>(i)]];
      return out;
    };
    const Eigen::MatrixXd& M = MassMatrix(model, data, q);
    Eigen::MatrixXd M_permuted(nv, nv);
    for (int i = 0; i < nv; ++i) {
      for (int j = 0; j < nv; ++j) {
        M_permuted(i, j) = M(pair.dof_to_v[static_cast<std::size_t>(i)], pair.dof_to_v[static_cast<std::size_t>(j)]);
      }
    }
    ExpectNear(pair.skeleton->getMassMatrix(), M_permuted, 1e-9, "mass matrix");

    ExpectNear(pair.skeleton->getGravityForces(), permute_vector(GravityTorques(model, data, q)), 1e-9,
               "gravity forces");

    const Eigen::VectorXd tau = InverseDynamics(model, data, q, v, a);
    pair.skeleton->setAccelerations(permute_vector(a));
    pair.skeleton->computeInverseDynamics(false, false, false);
    ExpectNear(DofValues(*pair.skeleton, &dart::dynamics::DegreeOfFreedom::getForce), permute_vector(tau), 1e-9,
               "inverse dynamics");

    Eigen::VectorXd tau_fd(nv);
    for (int i = 0; i < nv; ++i) tau_fd[i] = 10.0 * uniform(rng);
    const Eigen::VectorXd qdd = ForwardDynamics(model, data, q, v, tau_fd);
    // DART's articulated-body algorithm breaks down on the massless optical-frame links Atlas has (DART warns
    // it "can cause invalid physical behavior"); there, solve with DART's own mass matrix and bias forces.
    bool all_bodies_have_mass = true;
    for (std::size_t b = 0; b < pair.skeleton->getNumBodyNodes(); ++b) {
      all_bodies_have_mass = all_bodies_have_mass && pair.skeleton->getBodyNode(b)->getMass() > 0.0;
    }
    Eigen::VectorXd dart_qdd;
    if (all_bodies_have_mass) {
      pair.skeleton->setForces(permute_vector(tau_fd));
      pair.skeleton->computeForwardDynamics();
      dart_qdd = DofValues(*pair.skeleton, &dart::dynamics::DegreeOfFreedom::getAcceleration);
    } else {
      dart_qdd = pair.skeleton->getMassMatrix().ldlt().solve(permute_vector(tau_fd) -
                                                             pair.skeleton->getCoriolisAndGravityForces());
    }
    ExpectNear(dart_qdd, permute_vector(qdd), 1e-9, "forward dynamics");
  }
}

INSTANTIATE_TEST_SUITE_P(
    Robots, DartCrossCheckTest,
    ::testing::Values(std::make_tuple(test::AtlasUrdf(), true), std::make_tuple(test::AtlasUrdf(), false),
                      std::make_tuple(test::DrcHuboUrdf(), true), std::make_tuple(test::DrcHuboUrdf(), false)),
    [](const auto& info) {
      const std::string robot = std::get<0>(info.param).find("atlas") != std::string::npos ? "Atlas" : "DrcHubo";
      return robot + (std::get<1>(info.param) ? "Floating" : "Fixed");
    });

}  // namespace
}  // namespace cairn::multibody
