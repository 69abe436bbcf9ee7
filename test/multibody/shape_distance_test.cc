#include <cairn/multibody/shape_distance.h>

#include <random>

#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>

namespace cairn::multibody {
namespace {

// Every result must satisfy p_B - p_A = distance * normal with a unit normal (for overlapping boxes, only along
// the normal).
void ExpectConsistent(const ShapeDistance& d, bool normal_component_only = false) {
  EXPECT_NEAR(d.normal.norm(), 1.0, 1e-12);
  if (normal_component_only) {
    EXPECT_NEAR(d.normal.dot(d.p_B - d.p_A), d.distance, 1e-9);
  } else {
    EXPECT_LT((d.p_B - d.p_A - d.distance * d.normal).norm(), 1e-9);
  }
}

TEST(ShapeDistanceTest, Spheres) {
  const ShapeDistance d = SphereSphereDistance(Eigen::Vector3d(0, 0, 0), 1.0, Eigen::Vector3d(3, 0, 0), 0.5);
  EXPECT_DOUBLE_EQ(d.distance, 1.5);
  EXPECT_TRUE(d.p_A.isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(d.p_B.isApprox(Eigen::Vector3d(2.5, 0, 0)));
  const ShapeDistance overlap = SphereSphereDistance(Eigen::Vector3d(0, 0, 0), 1.0, Eigen::Vector3d(0, 1, 0), 0.5);
  EXPECT_DOUBLE_EQ(overlap.distance, -0.5);
  ExpectConsistent(overlap);
}

TEST(ShapeDistanceTest, CapsulesParallelCrossingAndEndToEnd) {
  // Crossing at right angles, 1 apart.
  const ShapeDistance cross = CapsuleCapsuleDistance(Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, 0, 0), 0.1,
                                                     Eigen::Vector3d(0, -1, 1), Eigen::Vector3d(0, 1, 1), 0.2);
  EXPECT_NEAR(cross.distance, 0.7, 1e-12);
  EXPECT_TRUE(cross.normal.isApprox(Eigen::Vector3d::UnitZ()));
  // Parallel overlapping segments.
  const ShapeDistance parallel = CapsuleCapsuleDistance(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0), 0.1,
                                                        Eigen::Vector3d(1, 0.5, 0), Eigen::Vector3d(3, 0.5, 0), 0.1);
  EXPECT_NEAR(parallel.distance, 0.3, 1e-12);
  ExpectConsistent(parallel);
  // End to end along one line.
  const ShapeDistance ends = CapsuleCapsuleDistance(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), 0.1,
                                                    Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(3, 0, 0), 0.1);
  EXPECT_NEAR(ends.distance, 0.8, 1e-12);
  const ShapeDistance sphere =
      SphereCapsuleDistance(Eigen::Vector3d(0.5, 0, 1), 0.25, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), 0.25);
  EXPECT_NEAR(sphere.distance, 0.5, 1e-12);
}

TEST(ShapeDistanceTest, BoxSphereOutsideAndInside) {
  const Pose X(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix(), Eigen::Vector3d(1, 2, 3));
  const Eigen::Vector3d size(2.0, 1.0, 0.5);
  // Straight above the top face.
  const ShapeDistance above = BoxSphereDistance(X, size, X * Eigen::Vector3d(0.2, 0.1, 1.25), 0.5);
  EXPECT_NEAR(above.distance, 0.5, 1e-12);
  EXPECT_TRUE(above.normal.isApprox(Eigen::Vector3d::UnitZ()));
  // Off a corner.
  const ShapeDistance corner = BoxSphereDistance(X, size, X * Eigen::Vector3d(2, 1.5, 0.25 + 1), 0.1);
  EXPECT_NEAR(corner.distance, std::sqrt(1.0 + 1.0 + 1.0) - 0.1, 1e-12);
  ExpectConsistent(corner);
  // Inside, nearest face is +y at depth 0.1.
  const ShapeDistance inside = BoxSphereDistance(X, size, X * Eigen::Vector3d(0.1, 0.4, 0.0), 0.2);
  EXPECT_NEAR(inside.distance, -0.3, 1e-12);
  EXPECT_TRUE(inside.normal.isApprox(X.rotation() * Eigen::Vector3d::UnitY()));
  ExpectConsistent(inside);
}

// Box-capsule equals the minimum of box-sphere along the axis (sampled densely).
TEST(ShapeDistanceTest, BoxCapsuleMatchesDenseSampling) {
  std::mt19937 rng(51);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Pose X(Eigen::AngleAxisd(3 * u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix(),
                 Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const Eigen::Vector3d size(0.5 + std::abs(u(rng)), 0.5 + std::abs(u(rng)), 0.2 + std::abs(u(rng)));
    const Eigen::Vector3d a(2 * u(rng), 2 * u(rng), 2 * u(rng)), b(2 * u(rng), 2 * u(rng), 2 * u(rng));
    const double r = 0.1;
    const ShapeDistance d = BoxCapsuleDistance(X, size, a, b, r);
    double sampled = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 20000; ++k) {
      sampled = std::min(sampled, BoxSphereDistance(X, size, a + (k / 20000.0) * (b - a), r).distance);
    }
    // The box's signed distance function is 1-Lipschitz, so sampling is off by at most half a step.
    EXPECT_LE(d.distance, sampled + 1e-12) << trial;
    EXPECT_GE(d.distance, sampled - 0.5 * (b - a).norm() / 20000.0 - 1e-12) << trial;
    ExpectConsistent(d);
  }
}

TEST(ShapeDistanceTest, BoxBoxKnownCases) {
  const Eigen::Vector3d unit(1, 1, 1);
  const Pose origin;
  // Face to face along x, 0.5 apart.
  const ShapeDistance faces =
      BoxBoxDistance(origin, unit, Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.5, 0.2, 0.1)), unit);
  EXPECT_NEAR(faces.distance, 0.5, 1e-12);
  EXPECT_TRUE(faces.normal.isApprox(Eigen::Vector3d::UnitX()));
  ExpectConsistent(faces);
  // A box standing on its corner 0.25 above the top face.
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(std::atan(std::sqrt(2.0)), Eigen::Vector3d(1, -1, 0).normalized())).toRotationMatrix();
  const double half_diagonal = 0.5 * std::sqrt(3.0);
  const ShapeDistance corner =
      BoxBoxDistance(origin, unit, Pose(R, Eigen::Vector3d(0.1, 0.1, 0.5 + 0.25 + half_diagonal)), unit);
  EXPECT_NEAR(corner.distance, 0.25, 1e-9);
  // Overlapping by 0.1 along z.
  const ShapeDistance overlap =
      BoxBoxDistance(origin, unit, Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.2, 0, 0.9)), unit);
  EXPECT_NEAR(overlap.distance, -0.1, 1e-12);
  EXPECT_TRUE(overlap.normal.isApprox(Eigen::Vector3d::UnitZ()));
  ExpectConsistent(overlap, true);
}

// Random box pairs against FCL's GJK/EPA (libccd) as an independent implementation.
TEST(ShapeDistanceTest, BoxBoxAgreesWithFcl) {
  std::mt19937 rng(52);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int separated = 0, overlapping = 0;
  for (int trial = 0; trial < 200; ++trial) {
    auto random_pose = [&] {
      return Pose(
          Eigen::AngleAxisd(3 * u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix(),
          Eigen::Vector3d(u(rng), u(rng), u(rng)));
    };
    const Pose XA = random_pose(), XB = random_pose();
    const Eigen::Vector3d sA(0.3 + std::abs(u(rng)), 0.3 + std::abs(u(rng)), 0.3 + std::abs(u(rng)));
    const Eigen::Vector3d sB(0.3 + std::abs(u(rng)), 0.3 + std::abs(u(rng)), 0.3 + std::abs(u(rng)));
    const ShapeDistance d = BoxBoxDistance(XA, sA, XB, sB);
    ExpectConsistent(d, d.distance < 0.0);
    fcl::CollisionObjectd a(std::make_shared<fcl::Boxd>(sA), XA.ToIsometry());
    fcl::CollisionObjectd b(std::make_shared<fcl::Boxd>(sB), XB.ToIsometry());
    fcl::DistanceRequestd request;
    request.enable_nearest_points = true;
    request.enable_signed_distance = true;
    request.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::DistanceResultd result;
    fcl::distance(&a, &b, request, result);
    if (d.distance > 0.0) {
      ++separated;
      EXPECT_NEAR(d.distance, result.min_distance, 1e-6) << trial;
    } else {
      ++overlapping;
      EXPECT_NEAR(d.distance, result.min_distance, 1e-4) << trial;
    }
  }
  EXPECT_GT(separated, 20);
  EXPECT_GT(overlapping, 20);
}

}  // namespace
}  // namespace cairn::multibody
