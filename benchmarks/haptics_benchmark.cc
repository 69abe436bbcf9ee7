// Haptic traversability affordances (seed 000, issue 20), with PCL as the peer for the point-cloud reductions
// (voxel grid, RANSAC sphere, octree change detection) when libpcl-dev is installed: the per-frame cost of describing the object in view
// and recalling it against a memory of 1,000 objects (the aim: at most 1 ms together), and of planning the
// antenna's interaction. Clouds are the simulated depth sensor's frames of data set 1 (200 x 150 pixels; a
// Kinect frame has 307,200, but the descriptor's 1 cm down-sampling leaves a few thousand points of either).

#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>
#ifdef CAIRN_HAVE_PCL
#include <pcl/filters/voxel_grid.h>
#include <pcl/octree/octree_pointcloud_changedetector.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_sphere.h>
#endif

#include "cairn/perception/haptics/affordance_descriptor.h"
#include "cairn/perception/haptics/haptic_interaction_planner.h"
#include "cairn/perception/haptics/background_subtractor.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"
#include "cairn/perception/haptics/sphere_ransac.h"
#include "cairn/perception/haptics/traversability_memory.h"
#include "cairn/perception/haptics/simulation/haptic_affordance_experiment.h"

namespace {

using namespace cairn::perception;

const HapticAffordanceExperiment& Experiment() {
  static const HapticAffordanceExperiment experiment;
  return experiment;
}

// A memory of `size` views of data set 1, labelled by ground truth.
TraversabilityMemory MakeMemory(int size) {
  TraversabilityMemory memory;
  const std::vector<HapticObjectKind> kinds = DataSet1();
  std::vector<AffordanceDescriptor> views;
  for (const HapticObjectKind kind : kinds) {
    for (int a = 0; a < 10; ++a) views.push_back(Experiment().Describe(Experiment().Observe(kind, a)));
  }
  for (int i = 0; i < size; ++i) {
    const std::size_t v = static_cast<std::size_t>(i) % views.size();
    memory.Add(views[v], MakeHapticObject(kinds[v / 10], 0).traversable());
  }
  return memory;
}

void BM_Descriptor(benchmark::State& state) {
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kShrub, 77);
  for (auto _ : state) benchmark::DoNotOptimize(Experiment().Describe(points));
  state.counters["points"] = static_cast<double>(points.cols());
}
BENCHMARK(BM_Descriptor)->Unit(benchmark::kMicrosecond);

void BM_Recall(benchmark::State& state) {
  const TraversabilityMemory memory = MakeMemory(static_cast<int>(state.range(0)));
  const AffordanceDescriptor observed = Experiment().Describe(Experiment().Observe(HapticObjectKind::kShrub, 77));
  for (auto _ : state) benchmark::DoNotOptimize(memory.Recall(observed));
}
BENCHMARK(BM_Recall)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// The per-frame figure of the issue: descriptor + recall against 1,000 memories.
void BM_DescriptorAndRecall1000(benchmark::State& state) {
  const TraversabilityMemory memory = MakeMemory(1000);
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kShrub, 77);
  for (auto _ : state) benchmark::DoNotOptimize(memory.Recall(Experiment().Describe(points)));
}
BENCHMARK(BM_DescriptorAndRecall1000)->Unit(benchmark::kMicrosecond);

void BM_InteractionPlan(benchmark::State& state) {
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kShrub, 77);
  const Eigen::Matrix3Xd object = KeepWithinReach(DownsampleByMinDistance(points, 0.01),
                                                  Experiment().options().X_CA.translation(), 1.0);
  const HapticInteractionPlanner planner;
  for (auto _ : state) benchmark::DoNotOptimize(planner.Plan(object, 0.3));
  state.counters["object_points"] = static_cast<double>(object.cols());
}
BENCHMARK(BM_InteractionPlan)->Unit(benchmark::kMicrosecond);

void BM_Gist(benchmark::State& state) {
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kWall, 3);
  for (auto _ : state) benchmark::DoNotOptimize(CountOccupiedVoxels(points, 0.01));
  state.counters["points"] = static_cast<double>(points.cols());
}
BENCHMARK(BM_Gist)->Unit(benchmark::kMicrosecond);

// Peers (PCL, same clouds; test/perception/haptics/pcl_cross_check_test.cc checks that the results agree).
// A wall frame (about 29,000 points) for the voxel grid and the change detection; a 200-point tip among 200 points
// of clutter for the sphere.
Eigen::Matrix3Xd TipCloud() {
  Eigen::Matrix3Xd points(3, 400);
  const Eigen::Vector3d center(0.1, -0.05, 0.9);
  for (int i = 0; i < 200; ++i) {
    const double u = (i + 0.5) / 200.0;
    const double phi = 2.399963 * i;
    const double z = -u;  // the half facing the sensor
    const double r = std::sqrt(1.0 - z * z);
    points.col(i) = center + 0.02 * Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z);
  }
  for (int i = 200; i < 400; ++i) points.col(i) = Eigen::Vector3d(-0.3 + 0.003 * (i - 200), 0.1 * std::sin(i), 1.3);
  return points;
}

void BM_CairnVoxelGrid(benchmark::State& state) {
  const Eigen::Matrix3Xd points = Experiment().Observe(HapticObjectKind::kWall, 3);
  for (auto _ : state) benchmark::DoNotOptimize(VoxelGridCentroids(points, 0.01));
}
BENCHMARK(BM_CairnVoxelGrid)->Unit(benchmark::kMicrosecond);

void BM_CairnSphereRansac(benchmark::State& state) {
  const Eigen::Matrix3Xd points = TipCloud();
  const SphereRansac ransac;
  for (auto _ : state) benchmark::DoNotOptimize(ransac.Fit(points));
}
BENCHMARK(BM_CairnSphereRansac)->Unit(benchmark::kMicrosecond);

void BM_CairnChangeDetection(benchmark::State& state) {
  const Eigen::Matrix3Xd reference = Experiment().Observe(HapticObjectKind::kWall, 3);
  const Eigen::Matrix3Xd scene = Experiment().Observe(HapticObjectKind::kWall, 4);
  for (auto _ : state) benchmark::DoNotOptimize(BackgroundSubtractor(reference, 0.01).Foreground(scene));
}
BENCHMARK(BM_CairnChangeDetection)->Unit(benchmark::kMicrosecond);

#ifdef CAIRN_HAVE_PCL
pcl::PointCloud<pcl::PointXYZ>::Ptr ToPcl(const Eigen::Matrix3Xd& points) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(points(0, i)), static_cast<float>(points(1, i)),
                                   static_cast<float>(points(2, i))));
  }
  return cloud;
}

void BM_PclVoxelGrid(benchmark::State& state) {
  const auto cloud = ToPcl(Experiment().Observe(HapticObjectKind::kWall, 3));
  for (auto _ : state) {
    pcl::VoxelGrid<pcl::PointXYZ> grid;
    grid.setInputCloud(cloud);
    grid.setLeafSize(0.01f, 0.01f, 0.01f);
    pcl::PointCloud<pcl::PointXYZ> filtered;
    grid.filter(filtered);
    benchmark::DoNotOptimize(filtered.size());
  }
}
BENCHMARK(BM_PclVoxelGrid)->Unit(benchmark::kMicrosecond);

void BM_PclSphereRansac(benchmark::State& state) {
  const auto cloud = ToPcl(TipCloud());
  for (auto _ : state) {
    pcl::SampleConsensusModelSphere<pcl::PointXYZ>::Ptr model(new pcl::SampleConsensusModelSphere<pcl::PointXYZ>(cloud));
    model->setRadiusLimits(0.005, 0.1);
    pcl::RandomSampleConsensus<pcl::PointXYZ> ransac(model);
    ransac.setDistanceThreshold(0.003);
    ransac.setMaxIterations(500);
    ransac.computeModel();
    std::vector<int> inliers;
    ransac.getInliers(inliers);
    benchmark::DoNotOptimize(inliers.size());
  }
}
BENCHMARK(BM_PclSphereRansac)->Unit(benchmark::kMicrosecond);

void BM_PclChangeDetection(benchmark::State& state) {
  const auto reference = ToPcl(Experiment().Observe(HapticObjectKind::kWall, 3));
  const auto scene = ToPcl(Experiment().Observe(HapticObjectKind::kWall, 4));
  for (auto _ : state) {
    pcl::octree::OctreePointCloudChangeDetector<pcl::PointXYZ> octree(0.01);
    octree.setInputCloud(reference);
    octree.addPointsFromInputCloud();
    octree.switchBuffers();
    octree.setInputCloud(scene);
    octree.addPointsFromInputCloud();
    std::vector<int> changed;
    octree.getPointIndicesFromNewVoxels(changed);
    benchmark::DoNotOptimize(changed.size());
  }
}
BENCHMARK(BM_PclChangeDetection)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace

BENCHMARK_MAIN();
