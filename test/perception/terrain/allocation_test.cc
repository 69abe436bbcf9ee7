// The per-update paths of the terrain maps allocate nothing once their scratch has grown: counted by replacing
// the global operator new in this test program.

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include <gtest/gtest.h>

#include "cairn/perception/terrain/elevation_fusion.h"
#include "cairn/perception/terrain/hierarchical_traversability.h"
#include "cairn/perception/terrain/map_registration.h"
#include "cairn/perception/terrain/semantic_fusion.h"
#include "cairn/perception/terrain/slope_roughness_filter.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// GCC (at -O1 with sanitizers) sees free() of what a new-expression returned and warns, not knowing that the
// replacement operator new above allocates with malloc.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace cairn::perception {
namespace {

TEST(TerrainAllocationTest, OneUpdateAllocatesNothingAfterWarmUp) {
  GridMap map(Eigen::Vector2i(60, 60), 0.05, Eigen::Vector2d::Zero());
  ElevationFusion::AddLayers(&map);
  ElevationFusion::Options eo;
  eo.num_threads = 2;
  ElevationFusion elevation(eo);
  SemanticFusion::Options so;
  so.num_threads = 2;
  SemanticFusion semantic(so);
  semantic.AddLayers(&map);
  SlopeRoughnessFilter::Options fo;
  fo.num_threads = 2;
  SlopeRoughnessFilter filter(fo);
  HierarchicalTraversability::Options to;
  to.num_threads = 2;
  HierarchicalTraversability traversability(to);
  GridMap global(Eigen::Vector2i(100, 100), 0.05, Eigen::Vector2d::Zero());
  MapRegistration registration({{"traversability", "traversability", 0.01, ""}}, 2);
  registration.AddLayers(&global);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.4, 1.4);
  Eigen::Matrix3Xd points(3, 5000);
  for (int k = 0; k < points.cols(); ++k) points.col(k) = Eigen::Vector3d(u(rng), u(rng), 0.01 * u(rng));
  Eigen::MatrixXd probabilities = Eigen::MatrixXd::Constant(2, points.cols(), 0.2);
  const Eigen::Vector3d sensor(0.0, -1.5, 1.0);
  auto update = [&] {
    elevation.Integrate(points, sensor, &map);
    semantic.Integrate(points, probabilities, &map);
    filter.Compute(&map);
    traversability.Compute(&map);
    registration.Register(map, &global);
  };
  const long start = g_allocations.load();
  update();  // warm-up: scratch and output layers
  EXPECT_GT(g_allocations.load(), start);  // the counter sees allocations at all
  const long before = g_allocations.load();
  update();
  update();
  EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace cairn::perception
