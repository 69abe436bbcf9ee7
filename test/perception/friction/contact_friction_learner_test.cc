// ContactFrictionLearner (issue 18, learning from touch): contacts are credited to the materials perception saw
// under the foot, in proportion to the segmenter's belief.
#include "cairn/perception/friction/contact_friction_learner.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// A floor of points every 2 cm over x in [0, 2), y in [-0.5, 0.5): ceramic where x < 1 (certain where y < 0.25,
// 90 % sure with 10 % marble beyond), wood where x >= 1 (certain).
FrictionPointCloud Floor(const MaterialRegistry& registry) {
  FrictionPointCloud cloud;
  std::vector<std::pair<int, float>> rows;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 50; ++j) cloud.points_W.emplace_back(0.01 + 0.02 * i, -0.49 + 0.02 * j, 0.0);
  }
  cloud.quantiles.assign(cloud.points_W.size(), 0.0f);
  cloud.weights = Eigen::MatrixXf::Zero(static_cast<Eigen::Index>(cloud.points_W.size()), registry.size());
  for (std::size_t k = 0; k < cloud.points_W.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    if (cloud.points_W[k].x() < 1.0 && cloud.points_W[k].y() < 0.25) {
      cloud.weights(row, registry.IndexOf("ceramic")) = 1.0f;
    } else if (cloud.points_W[k].x() < 1.0) {
      cloud.weights(row, registry.IndexOf("ceramic")) = 0.9f;
      cloud.weights(row, registry.IndexOf("marble")) = 0.1f;
    } else {
      cloud.weights(row, registry.IndexOf("wood")) = 1.0f;
    }
  }
  return cloud;
}

FootContact Slip(double x, double y, double mu) { return {Eigen::Vector3d(x, y, 0.0), ContactObservation::Slipped(mu)}; }

// Wet tiles: the segmenter says ceramic (Table 3.3: N(0.97, 0.05)), the feet slip at 0.3. Where it was sure, the
// learner lowers ceramic's belief and leaves wood, never under a slipping foot, as it was.
TEST(ContactFrictionLearnerTest, CreditsSlipsToTheMaterialsSeenUnderTheFoot) {
  const MaterialRegistry table = MaterialRegistry::ThesisTable33();
  const ContactFrictionLearner learner(table, 0.1);
  auto context = learner.CreateDefaultContext();
  learner.get_friction_points_input_port().FixValue(context.get(), Floor(table));
  std::vector<FootContact> log = {Slip(0.3, 0.1, 0.3), Slip(0.5, -0.1, 0.3), Slip(0.7, 0.1, 0.3)};
  learner.get_contacts_input_port().FixValue(context.get(), log);
  learner.ExecuteForcedEvents(context.get());
  const ContactLearning& learned = learner.learning(*context);
  EXPECT_EQ(learned.seen, 3);
  EXPECT_EQ(learned.learned, 3);
  EXPECT_EQ(learned.skipped, 0);
  const auto mean = [](const MaterialRegistry& r, const char* label) { return r.material(r.IndexOf(label)).friction.Mean(); };
  const auto q05 = [](const MaterialRegistry& r, const char* label) {
    return r.material(r.IndexOf(label)).friction.Quantile(0.05);
  };
  const MaterialRegistry& after = learner.get_registry_output_port().Eval<MaterialRegistry>(*context);
  EXPECT_LT(mean(after, "ceramic"), 0.3);
  EXPECT_LT(q05(after, "ceramic"), q05(table, "ceramic") - 0.4);
  EXPECT_DOUBLE_EQ(mean(after, "wood"), mean(table, "wood"));
  EXPECT_DOUBLE_EQ(mean(after, "marble"), mean(table, "marble"));
  EXPECT_EQ(after.material(after.IndexOf("ceramic")).num_contacts, 3);
  EXPECT_EQ(after.material(after.IndexOf("wood")).num_contacts, 0);
  // The same log again: nothing new to learn.
  learner.ExecuteForcedEvents(context.get());
  EXPECT_DOUBLE_EQ(mean(learner.learning(*context).registry, "ceramic"), mean(after, "ceramic"));
  // One more contact, off the perceived floor: read and skipped.
  log.push_back(Slip(3.0, 0.0, 0.3));
  learner.get_contacts_input_port().FixValue(context.get(), log);
  learner.ExecuteForcedEvents(context.get());
  EXPECT_EQ(learner.learning(*context).seen, 4);
  EXPECT_EQ(learner.learning(*context).skipped, 1);
  // Where the segmenter kept a tenth on marble, a slip ceramic can hardly explain (0.3 is 13 standard deviations
  // below its table mean, 3.5 below marble's) is put on marble: the update weighs each label by how well it
  // explains the contact (MaterialRegistry::UpdateFromContact), so the less likely label takes the blame.
  const ContactFrictionLearner fresh(table, 0.1);
  auto mixed = fresh.CreateDefaultContext();
  fresh.get_friction_points_input_port().FixValue(mixed.get(), Floor(table));
  fresh.get_contacts_input_port().FixValue(mixed.get(), std::vector<FootContact>{Slip(0.5, 0.4, 0.3)});
  fresh.ExecuteForcedEvents(mixed.get());
  const MaterialRegistry& blamed = fresh.learning(*mixed).registry;
  EXPECT_LT(mean(blamed, "marble"), mean(table, "marble") - 0.3);
  EXPECT_NEAR(mean(blamed, "ceramic"), mean(table, "ceramic"), 1e-3);
  // A contact the registry cannot use (a measurement of friction 20) and one at a NaN position: set aside, and
  // learning goes on.
  log.push_back({Eigen::Vector3d(0.5, 0.0, 0.0), ContactObservation::Measured(20.0, 0.05)});
  log.push_back({Eigen::Vector3d(std::nan(""), 0.0, 0.0), ContactObservation::Slipped(0.3)});
  log.push_back(Slip(0.4, 0.1, 0.3));
  learner.get_contacts_input_port().FixValue(context.get(), log);
  learner.ExecuteForcedEvents(context.get());
  EXPECT_EQ(learner.learning(*context).seen, 7);
  EXPECT_EQ(learner.learning(*context).rejected, 1);
  EXPECT_EQ(learner.learning(*context).skipped, 2);
  EXPECT_EQ(learner.learning(*context).learned, 4);
  // A shorter log is not a continuation of this one.
  log.resize(2);
  learner.get_contacts_input_port().FixValue(context.get(), log);
  CAIRN_EXPECT_THROWS_WITH(learner.ExecuteForcedEvents(context.get()), std::logic_error,
                           "the contact log shrank from 7 to 2 contacts");
}

// The learned registry is saved atomically and reads back as learned.
TEST(ContactFrictionLearnerTest, TheLearnedRegistryRoundTripsThroughYaml) {
  const MaterialRegistry table = MaterialRegistry::ThesisTable33();
  const ContactFrictionLearner learner(table, 0.1);
  auto context = learner.CreateDefaultContext();
  learner.get_friction_points_input_port().FixValue(context.get(), Floor(table));
  learner.get_contacts_input_port().FixValue(
      context.get(), std::vector<FootContact>{{Eigen::Vector3d(1.5, 0.0, 0.0), ContactObservation::Measured(0.5, 0.05)}});
  learner.ExecuteForcedEvents(context.get());
  const MaterialRegistry& learned = learner.learning(*context).registry;
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("cairn_learned_registry_" + std::to_string(::getpid()) + ".yaml")).string();
  learned.SaveYaml(path);
  const MaterialRegistry loaded = MaterialRegistry::LoadYaml(path);
  std::filesystem::remove(path);
  const int wood = learned.IndexOf("wood");
  EXPECT_NEAR(loaded.material(wood).friction.Mean(), learned.material(wood).friction.Mean(), 1e-9);
  EXPECT_EQ(loaded.material(wood).num_contacts, 1);
  EXPECT_LT(learned.material(wood).friction.Mean(), table.material(wood).friction.Mean());  // 0.88 -> towards 0.5
}

TEST(ContactFrictionLearnerTest, RejectsBadSettingsAndPoints) {
  const MaterialRegistry table = MaterialRegistry::ThesisTable33();
  CAIRN_EXPECT_THROWS_WITH(ContactFrictionLearner(MaterialRegistry(), 0.1), std::invalid_argument,
                           "the registry is empty");
  CAIRN_EXPECT_THROWS_WITH(ContactFrictionLearner(table, 0.0), std::invalid_argument,
                           "period 0 s must be positive and finite");
  CAIRN_EXPECT_THROWS_WITH(ContactFrictionLearner(table, 0.1, -1.0), std::invalid_argument,
                           "radius -1 m must be in (0, 10]");
  const ContactFrictionLearner learner(table, 0.1);
  FrictionPointCloud bad;
  bad.points_W.emplace_back(0.0, 0.0, 0.0);
  bad.quantiles.push_back(0.0f);
  bad.weights = Eigen::MatrixXf::Zero(1, 3);
  Eigen::VectorXd mixture;
  CAIRN_EXPECT_THROWS_WITH(learner.MixtureUnder(bad, Eigen::Vector3d::Zero(), &mixture), std::invalid_argument,
                           "give one row of 14 registry-order weights per point");
}

}  // namespace
}  // namespace cairn::perception
