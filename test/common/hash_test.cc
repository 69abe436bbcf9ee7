#include "cairn/common/hash.h"

#include <string>

#include <gtest/gtest.h>

namespace cairn {
namespace {

// Values of the two FNV-1a copies this function replaced (walking model and transition oracle); oracle files
// store them, so they must never change.
TEST(HashTest, KeepsTheValuesThatFilesStore) {
  EXPECT_EQ(Fnv1a64(""), 0x14650fb0739d0383ULL);
  EXPECT_EQ(Fnv1a64(""), kFnv1a64OffsetBasis);
  EXPECT_EQ(Fnv1a64("a"), 0x44bd8ad473cd9906ULL);
  EXPECT_EQ(Fnv1a64("cairn-transition-oracle 1"), 0xe517c2fb477fd498ULL);
  std::string all_bytes;
  for (int c = 0; c < 256; ++c) all_bytes.push_back(static_cast<char>(c));
  EXPECT_EQ(Fnv1a64(all_bytes), 0x16d173bdfcdae583ULL);  // bytes >= 0x80 hash as unsigned
}

TEST(HashTest, ChainingHashesTheConcatenation) {
  EXPECT_EQ(Fnv1a64("model.urdf", Fnv1a64("walking.yaml")), Fnv1a64("walking.yamlmodel.urdf"));
  EXPECT_NE(Fnv1a64("ab"), Fnv1a64("ba"));
  const std::string with_nul("a\0b", 3);
  EXPECT_NE(Fnv1a64(with_nul), Fnv1a64("ab"));  // embedded zero bytes count
}

TEST(HashTest, HexHasSixteenLowerCaseDigits) {
  EXPECT_EQ(HashHex(0x14650fb0739d0383ULL), "14650fb0739d0383");
  EXPECT_EQ(HashHex(0), "0000000000000000");
  EXPECT_EQ(HashHex(0xFFFFFFFFFFFFFFFFULL), "ffffffffffffffff");
}

}  // namespace
}  // namespace cairn
