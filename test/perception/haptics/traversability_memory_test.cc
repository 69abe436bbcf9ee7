#include "cairn/perception/haptics/traversability_memory.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::perception {
namespace {

AffordanceDescriptor One(double n, double s, double d, double m) {
  return AffordanceDescriptor::FromValues(Eigen::Vector4d(n, s, d, m));
}

std::string TempPath(const std::string& name) {
  return std::string(CAIRN_BINARY_DIR) + "/traversability_memory_test_" + name;
}

TEST(TraversabilityMemoryTest, GlobalDissimilarityByHand) {
  const TraversabilityMemory::Options options;  // ζ, β, γ, δ = 0.5, 0.2, 2, 2
  // Φn = Γ(0.5·1) = 0.5, Φs = Γ(0.2·2) = 0.4, Φd = Γ(2·1/1) = 1 (clamped), Φm = Γ(2·1/4) = 0.5: (2.4) / 4.
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(One(2, 3, 1, 4), One(3, 1, 2, 3), options), 0.6);
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(One(2, 3, 1, 4), One(2, 3, 1, 4), options), 0.0);
  // Eqs. 9–10 divide by the observed value: not symmetric.
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(One(1, 1, 4, 4), One(1, 1, 2, 2), options), 0.5);
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(One(1, 1, 2, 2), One(1, 1, 4, 4), options), 0.5);
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(One(1, 1, 4, 8), One(1, 1, 3, 7), options),
                   (0.5 + 0.25) / 4.0);
  // An observed zero: 0 against 0, 1 against anything else.
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(One(0, 0, 0, 0), One(0, 0, 0, 0), options), 0.0);
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(One(0, 0, 0, 0), One(0, 0, 1, 1), options), 0.5);
  // Two lines average over 8 terms.
  Eigen::VectorXd a(8), b(8);
  a << 2, 3, 1, 4, 0, 0, 0, 0;
  b << 3, 1, 2, 3, 0, 0, 0, 0;
  EXPECT_DOUBLE_EQ(TraversabilityMemory::Dissimilarity(AffordanceDescriptor::FromValues(a),
                                                       AffordanceDescriptor::FromValues(b), options),
                   2.4 / 8.0);
}

TraversabilityMemory HandMemory() {
  TraversabilityMemory memory(TraversabilityMemory::Options{}, 1);
  memory.Add(One(2, 3, 1, 4), true);   // Φ = 0
  memory.Add(One(3, 1, 2, 3), false);  // Φ = 0.6
  memory.Add(One(2, 3, 1, 3), true);   // Φ = 0.5 / 4 = 0.125
  memory.Add(One(4, 3, 1, 4), false);  // Φ = 1 / 4 = 0.25
  return memory;
}

TEST(TraversabilityMemoryTest, KnnConfidencesByHand) {
  const TraversabilityMemory memory = HandMemory();
  const AffordanceDescriptor o = One(2, 3, 1, 4);
  const AffordanceRecall k3 = memory.Recall(o, 3);
  EXPECT_EQ(k3.neighbours, 3);
  EXPECT_DOUBLE_EQ(k3.confidence_traversable, (1.0 + 0.875) / 3.0);  // eq. 12
  EXPECT_DOUBLE_EQ(k3.confidence_non_traversable, 0.75 / 3.0);      // eq. 13
  EXPECT_TRUE(k3.traversable);                                       // eq. 14
  EXPECT_DOUBLE_EQ(k3.confidence, 0.625);                            // eq. 15
  EXPECT_EQ(k3.nearest, 0);
  // k = 5 with four entries: every entry counts and the sums are still divided by k.
  const AffordanceRecall k5 = memory.Recall(o);
  EXPECT_EQ(k5.neighbours, 4);
  EXPECT_DOUBLE_EQ(k5.confidence_traversable, 1.875 / 5.0);
  EXPECT_DOUBLE_EQ(k5.confidence_non_traversable, (0.75 + 0.4) / 5.0);
  const AffordanceRecall k1 = memory.Recall(One(4, 3, 1, 4), 1);
  EXPECT_FALSE(k1.traversable);
  EXPECT_DOUBLE_EQ(k1.confidence, 1.0);
}

TEST(TraversabilityMemoryTest, EmptyMemoryAndTiesAreCautious) {
  TraversabilityMemory memory(TraversabilityMemory::Options{}, 1);
  const AffordanceRecall empty = memory.Recall(One(1, 1, 1, 1));
  EXPECT_FALSE(empty.traversable);
  EXPECT_EQ(empty.confidence, 0.0);
  EXPECT_EQ(empty.nearest, -1);
  memory.Add(One(1, 1, 1, 1), true);
  memory.Add(One(1, 1, 1, 1), false);
  const AffordanceRecall tie = memory.Recall(One(1, 1, 1, 1), 2);
  EXPECT_FALSE(tie.traversable);
  EXPECT_DOUBLE_EQ(tie.confidence, 0.5);
  // Equal dissimilarities keep the older entry as the nearest.
  EXPECT_EQ(memory.Recall(One(1, 1, 1, 1), 1).nearest, 0);
  EXPECT_TRUE(memory.Recall(One(1, 1, 1, 1), 1).traversable);
}

TEST(TraversabilityMemoryTest, SaveLoadRoundTripsExactly) {
  TraversabilityMemory::Options options;
  options.k = 3;
  options.zeta = 0.1 + 0.2;  // not representable in short form: must round-trip exactly
  TraversabilityMemory memory(options, 1);
  memory.Add(One(2, 3, 1.0 / 3.0, 4), true);
  memory.Add(One(3, 1, 2, 3), false);
  const std::string path = TempPath("roundtrip.txt");
  memory.Save(path);
  const TraversabilityMemory loaded = TraversabilityMemory::Load(path);
  EXPECT_EQ(loaded.size(), 2);
  EXPECT_EQ(loaded.options().k, 3);
  EXPECT_EQ(loaded.options().zeta, options.zeta);
  EXPECT_EQ(loaded.descriptor(0).values(), memory.descriptor(0).values());
  EXPECT_TRUE(loaded.traversable(0));
  EXPECT_FALSE(loaded.traversable(1));
  EXPECT_EQ(loaded.ToText(), memory.ToText());
  std::remove(path.c_str());
}

TEST(TraversabilityMemoryTest, MalformedFilesNameTheLineAndValue) {
  const std::string good = HandMemory().ToText();
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText("hello 1\n", "m.txt"), std::runtime_error, "m.txt:1:",
                           "not a traversability memory");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("zeta 0.5", "zeta abc"), "m.txt"),
                           std::runtime_error, "m.txt:2:", "zeta 'abc' is not a finite number");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("zeta 0.5", "zeta -1"), "m.txt"),
                           std::runtime_error, "zeta is -1");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("entries 4", "entries 100001"), "m.txt"),
                           std::runtime_error, "entries '100001' is not an integer between 0 and 100000");
  // A header asking for far more entries than the file holds fails before memory is reserved for them.
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("entries 4", "entries 100000"), "m.txt"),
                           std::runtime_error, "declares 100000 entries of 5 fields", "truncated");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("entries 4", "entries 5"), "m.txt"),
                           std::runtime_error, "ends where entry 4 was expected");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("entries 4", "entries 3"), "m.txt"),
                           std::runtime_error, "m.txt:12:", "after the 3 declared entries");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("\n1 2 3 1 4", "\n2 2 3 1 4"), "m.txt"),
                           std::runtime_error, "m.txt:9:", "label '2'");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("\n1 2 3 1 4", "\n1 2 3 1"), "m.txt"),
                           std::runtime_error, "entry 0 has 4 fields; expected the label and 4 values");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("\n1 2 3 1 4", "\n1 2 -3 1 4"), "m.txt"),
                           std::runtime_error, "value 1 is negative: -3");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::FromText(replace("\n1 2 3 1 4", "\n1 2 nan 1 4"), "m.txt"),
                           std::runtime_error, "value 1 'nan' is not a finite number");
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory::Load(TempPath("missing.txt")), std::runtime_error,
                           "cannot read the memory file", "missing.txt");
}

TEST(TraversabilityMemoryTest, BadUseNamesTheValue) {
  TraversabilityMemory::Options options;
  options.k = 0;
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory{options}, std::invalid_argument, "k is 0", "between 1 and 64");
  options = {};
  options.gamma = 0.0;
  CAIRN_EXPECT_THROWS_WITH(TraversabilityMemory{options}, std::invalid_argument, "gamma is 0");
  TraversabilityMemory memory;
  CAIRN_EXPECT_THROWS_WITH(memory.Add(One(1, 1, 1, 1), true), std::invalid_argument,
                           "has 1 lines but the memory holds 14-line");
  CAIRN_EXPECT_THROWS_WITH(memory.Recall(AffordanceDescriptor(14), 65), std::invalid_argument, "k is 65");
  CAIRN_EXPECT_THROWS_WITH(memory.descriptor(0), std::out_of_range, "entry 0 does not exist");
}

}  // namespace
}  // namespace cairn::perception
