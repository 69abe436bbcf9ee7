// Known answers for BulletPlant's contacts and integration: a block on an incline holds when tan θ < μ and slides
// at g (sin θ − μ cos θ) otherwise; a block pushed over flat ground decelerates at μ g, per terrain region; the
// contact forces of a resting block balance its weight; a pendulum swings with its exact period.

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <cairn/multibody/model_builder.h>
#include <cairn/multibody/plant/bullet_plant.h>

namespace cairn::multibody {
namespace {

constexpr double kG = 9.81;
constexpr double kPi = 3.14159265358979323846;

// A floating 1 kg box of side lengths `size` with its collision box.
Model BlockModel(const Eigen::Vector3d& size) {
  ModelBuilder builder("block");
  Body body;
  body.name = "block";
  const double m = 1.0;
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  I(0, 0) = m * (size.y() * size.y() + size.z() * size.z()) / 12.0;
  I(1, 1) = m * (size.x() * size.x() + size.z() * size.z()) / 12.0;
  I(2, 2) = m * (size.x() * size.x() + size.y() * size.y()) / 12.0;
  body.inertia = SpatialInertia::FromMassComInertia(m, Eigen::Vector3d::Zero(), I);
  body.has_inertial = true;
  Joint joint;
  joint.name = "root_joint";
  joint.type = JointType::kFloating;
  const int index = builder.AddBody(0, body, joint);
  Geometry box;
  box.name = "block_box";
  box.type = GeometryType::kBox;
  box.size = size;
  builder.AddCollisionGeometry(index, box);
  return builder.Build();
}

// The configuration of a floating body at position p with rotation R.
Eigen::VectorXd FloatingQ(const Eigen::Vector3d& p, const Eigen::Matrix3d& R) {
  Eigen::VectorXd q(7);
  const Eigen::Quaterniond quaternion(R);
  q << p, quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z();
  return q;
}

// A terrain box whose top face is the plane through `origin` with rotation R (top face normal R e_z).
TerrainBox Slab(const std::string& name, const Eigen::Matrix3d& R, const Eigen::Vector3d& origin,
                const Eigen::Vector3d& size, double friction) {
  TerrainBox box;
  box.name = name;
  box.X_WB = Pose(R, origin - R * Eigen::Vector3d(0.0, 0.0, 0.5 * size.z()));
  box.size = size;
  box.friction = friction;
  return box;
}

struct InclineRun {
  double displacement_half = 0.0;  // along the downhill direction at t = 0.5 s
  double displacement_end = 0.0;   // at t = 1 s
  double speed_half = 0.0;
  double speed_end = 0.0;
  Eigen::Vector3d mean_contact_force = Eigen::Vector3d::Zero();  // over the second half
};

InclineRun RunIncline(double theta, double mu) {
  const Eigen::Vector3d size(0.2, 0.2, 0.1);
  const Model model = BlockModel(size);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
  BulletPlant plant(model, {Slab("incline", R, Eigen::Vector3d::Zero(), Eigen::Vector3d(40.0, 4.0, 1.0), mu)});
  const Eigen::Vector3d p0 = R * Eigen::Vector3d(0.0, 0.0, 0.5 * size.z());
  plant.SetState(FloatingQ(p0, R), Eigen::VectorXd::Zero(6));
  const Eigen::Vector3d downhill = R * Eigen::Vector3d::UnitX();
  InclineRun run;
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(6);
  for (int step = 1; step <= 1000; ++step) {
    plant.Step(tau);
    if (step > 500) {
      for (const ContactPoint& c : plant.contacts()) run.mean_contact_force += (c.normal_force * c.normal + c.tangential_force) / 500.0;
    }
    const Eigen::VectorXd q = plant.positions();
    const Eigen::VectorXd v = plant.velocities();
    const Eigen::Matrix3d R_WB = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).toRotationMatrix();
    const double along = (q.head<3>() - p0).dot(downhill);
    const double speed = (R_WB * v.tail<3>()).dot(downhill);
    if (step == 500) {
      run.displacement_half = along;
      run.speed_half = speed;
    }
    if (step == 1000) {
      run.displacement_end = along;
      run.speed_end = speed;
    }
  }
  return run;
}

TEST(BulletPlantContactTest, BlockOnInclineHoldsWhenTanThetaBelowMu) {
  for (const double theta_deg : {10.0, 20.0}) {
    const double theta = theta_deg * kPi / 180.0;
    const double mu = std::tan(theta) + 0.1;
    const InclineRun run = RunIncline(theta, mu);
    // Stated tolerance: creep below 0.1 mm over 1 s.
    EXPECT_LT(std::abs(run.displacement_end), 1e-4) << theta_deg << " deg";
    // The terrain carries the weight: the contact forces balance m g (1 kg) within 1 %.
    EXPECT_NEAR(run.mean_contact_force.z(), kG, 0.01 * kG) << theta_deg << " deg";
    EXPECT_NEAR(run.mean_contact_force.x(), 0.0, 0.01 * kG) << theta_deg << " deg";
  }
}

TEST(BulletPlantContactTest, BlockOnInclineSlidesAtGTimesSinMinusMuCos) {
  for (const auto& [theta_deg, mu] : std::vector<std::pair<double, double>>{{30.0, 0.2}, {25.0, 0.1}, {45.0, 0.6}}) {
    const double theta = theta_deg * kPi / 180.0;
    ASSERT_GT(std::tan(theta), mu);
    const double expected = kG * (std::sin(theta) - mu * std::cos(theta));
    const InclineRun run = RunIncline(theta, mu);
    const double measured = (run.speed_end - run.speed_half) / 0.5;
    // Stated tolerance: 1 % of the expected acceleration.
    EXPECT_NEAR(measured, expected, 0.01 * expected) << theta_deg << " deg, mu " << mu;
    RecordProperty("incline_" + std::to_string(static_cast<int>(theta_deg)),
                   std::to_string(measured) + " vs " + std::to_string(expected));
  }
}

TEST(BulletPlantContactTest, PushedBlockDeceleratesAtMuGOnEachRegion) {
  const Eigen::Vector3d size(0.2, 0.2, 0.1);
  const Model model = BlockModel(size);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  // Ice for x < 0, carpet for x > 0: each region is its own body with its own friction.
  const double mu_ice = 0.1, mu_carpet = 0.5;
  BulletPlant plant(model, {Slab("ice", I, Eigen::Vector3d(-5.0, 0.0, 0.0), Eigen::Vector3d(10.0, 4.0, 1.0), mu_ice),
                            Slab("carpet", I, Eigen::Vector3d(5.0, 0.0, 0.0), Eigen::Vector3d(10.0, 4.0, 1.0),
                                 mu_carpet)});
  Eigen::VectorXd v = Eigen::VectorXd::Zero(6);
  v[3] = 3.0;  // body-frame x velocity (the body is not rotated)
  plant.SetState(FloatingQ(Eigen::Vector3d(-2.0, 0.0, 0.5 * size.z()), I), v);
  // Speeds sampled every step; the deceleration is measured where the 0.2 m block lies wholly on the ice
  // (x < -0.1) or wholly on the carpet (x > 0.1).
  std::vector<double> t_ice, v_ice, t_carpet, v_carpet;
  std::vector<ContactPoint> last_sliding_contacts;
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(6);
  for (int step = 1; step <= 3000; ++step) {
    plant.Step(tau);
    const double x = plant.positions()[0];
    const double speed = plant.velocities()[3];
    if (speed < 0.05) break;
    last_sliding_contacts = plant.contacts();
    if (x < -0.1 && x > -1.9) {
      t_ice.push_back(plant.time());
      v_ice.push_back(speed);
    } else if (x > 0.1) {
      t_carpet.push_back(plant.time());
      v_carpet.push_back(speed);
    }
  }
  ASSERT_GT(t_ice.size(), 100u);
  ASSERT_GT(t_carpet.size(), 20u);
  const double decel_ice = (v_ice.front() - v_ice.back()) / (t_ice.back() - t_ice.front());
  const double decel_carpet = (v_carpet.front() - v_carpet.back()) / (t_carpet.back() - t_carpet.front());
  // Stated tolerance: 1 % of mu g.
  EXPECT_NEAR(decel_ice, mu_ice * kG, 0.01 * mu_ice * kG);
  EXPECT_NEAR(decel_carpet, mu_carpet * kG, 0.01 * mu_carpet * kG);
  RecordProperty("deceleration_ice", std::to_string(decel_ice));
  RecordProperty("deceleration_carpet", std::to_string(decel_carpet));
  // The reported friction on the sliding block opposes the motion with |F_t| = mu F_n.
  double ft = 0.0, fn = 0.0;
  ASSERT_FALSE(last_sliding_contacts.empty());
  for (const ContactPoint& c : last_sliding_contacts) {
    ft += c.tangential_force.x();
    fn += c.normal_force;
    EXPECT_EQ(c.terrain, 1);
  }
  EXPECT_NEAR(ft, -mu_carpet * fn, 0.01 * mu_carpet * fn);
}

// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean.
double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next_a;
  }
  return kPi / (2.0 * a);
}

TEST(BulletPlantContactTest, PendulumSwingsWithItsExactPeriod) {
  // A 1 kg bob (a 5 cm sphere's inertia) 1 m below a horizontal hinge on a fixed base.
  ModelBuilder builder("pendulum");
  Body bob;
  bob.name = "bob";
  const double m = 1.0, d = 1.0, r = 0.05;
  const double I_com = 0.4 * m * r * r;
  bob.inertia = SpatialInertia::FromMassComInertia(m, Eigen::Vector3d(0.0, 0.0, -d), I_com * Eigen::Matrix3d::Identity());
  Joint hinge;
  hinge.name = "hinge";
  hinge.type = JointType::kRevolute;
  hinge.axis = Eigen::Vector3d::UnitY();
  builder.AddBody(0, bob, hinge);
  const Model model = builder.Build();
  BulletPlantOptions options;
  options.contacts = false;
  BulletPlant plant(model, {}, options);
  const double theta0 = 0.5;
  plant.SetState(Eigen::VectorXd::Constant(1, theta0), Eigen::VectorXd::Zero(1));
  const double I_hinge = I_com + m * d * d;
  const double expected = 4.0 * std::sqrt(I_hinge / (m * kG * d)) * EllipticK(std::sin(0.5 * theta0));
  // Downward zero crossings, linearly interpolated.
  std::vector<double> crossings;
  double previous = theta0;
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(1);
  for (int step = 1; step <= 20000; ++step) {
    plant.Step(tau);
    const double theta = plant.positions()[0];
    if (previous > 0.0 && theta <= 0.0) {
      crossings.push_back(plant.time() - options.time_step * theta / (theta - previous));
    }
    previous = theta;
  }
  ASSERT_GE(crossings.size(), 5u);
  const double measured = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  // Stated tolerance: 1e-3 relative (semi-implicit Euler at 1 ms is symplectic; its period error is O(h^2)).
  EXPECT_NEAR(measured, expected, 1e-3 * expected);
  RecordProperty("period", std::to_string(measured) + " vs " + std::to_string(expected));
  // No dissipation: the amplitude after 20 s is still theta0 within 1 %.
  double amplitude = 0.0;
  for (int step = 0; step < 3000; ++step) {
    plant.Step(tau);
    amplitude = std::max(amplitude, std::abs(plant.positions()[0]));
  }
  EXPECT_NEAR(amplitude, theta0, 0.01 * theta0);
}

}  // namespace
}  // namespace cairn::multibody
