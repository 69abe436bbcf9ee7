#include "cairn/systems/primitives/vector_log_sink.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(VectorLogSinkTest, RecordsOnForcedPublishAndWritesCsv) {
  VectorLogSink sink(2);
  auto context = sink.CreateDefaultContext();
  sink.get_input_port().FixValue(context.get(), Eigen::Vector2d(1.0, 0.1));
  sink.ForcedPublish(*context);
  context->SetTime(0.5);
  sink.get_input_port().FixValue(context.get(), Eigen::Vector2d(2.0, 0.2));
  sink.ForcedPublish(*context);
  const VectorLog& log = sink.GetLog(*context);
  ASSERT_EQ(log.num_samples(), 2);
  EXPECT_EQ(log.sample_times()[1], 0.5);
  EXPECT_EQ(log.data()(1, 1), 0.2);

  const auto path = std::filesystem::temp_directory_path() / "cairn_vector_log_sink_test.csv";
  log.WriteCsv(path.string(), {"a", "b"});
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "time,a,b\n0,1,0.10000000000000001\n0.5,2,0.20000000000000001\n");
  std::filesystem::remove(path);
  CAIRN_EXPECT_THROWS_WITH(log.WriteCsv(path.string(), {"only_one"}), std::invalid_argument, "1 column names",
                           "size 2");
}

TEST(VectorLogSinkTest, RejectsBadSizesAndPeriods) {
  CAIRN_EXPECT_THROWS_WITH(VectorLogSink(0), std::invalid_argument, "size must be positive");
  CAIRN_EXPECT_THROWS_WITH(VectorLogSink(1, -0.1), std::invalid_argument, "publish_period must be >= 0");
  VectorLog log(2);
  CAIRN_EXPECT_THROWS_WITH(log.AddData(0.0, Eigen::VectorXd::Zero(3)), std::invalid_argument, "size 3");
  // NaN compared false with 0 and silently meant "every step" before.
  CAIRN_EXPECT_THROWS_WITH(VectorLogSink(1, std::nan("")), std::invalid_argument, "publish_period", "got nan");
  CAIRN_EXPECT_THROWS_WITH(VectorLogSink(1, HUGE_VAL), std::invalid_argument, "publish_period", "got inf");
  CAIRN_EXPECT_THROWS_WITH(VectorLogSink(1, 0.1, 0), std::invalid_argument, "capacity must be >= 1 sample; got 0");
  CAIRN_EXPECT_THROWS_WITH(VectorLog(-1), std::invalid_argument, "size must be >= 0; got -1");
  CAIRN_EXPECT_THROWS_WITH(log.AddData(std::nan(""), Eigen::VectorXd::Zero(2)), std::invalid_argument,
                           "sample time nan");
}

TEST(VectorLogSinkTest, ALogHoldsAtMostItsCapacity) {
  EXPECT_EQ(VectorLog(3).capacity(), VectorLog::kDefaultCapacity);
  VectorLog log(1, 2);
  log.AddData(0.0, Eigen::VectorXd::Zero(1));
  log.AddData(0.1, Eigen::VectorXd::Zero(1));
  CAIRN_EXPECT_THROWS_WITH(log.AddData(0.2, Eigen::VectorXd::Zero(1)), std::runtime_error,
                           "capacity of 2 samples", "t = 0.2", "publish period", "larger capacity");
  EXPECT_EQ(log.num_samples(), 2);
  VectorLogSink sink(1, 0.0, 1);
  auto context = sink.CreateDefaultContext();
  EXPECT_EQ(sink.GetLog(*context).capacity(), 1);
}

}  // namespace
}  // namespace cairn::systems
