// Paged heights never make a live frame wait (issue 16): when the view
// jumps onto tiles that are not resident, the two-level method keeps Level1
// on its last square (level1_held), reads nothing on the frame's thread, and
// moves Level1 once the background thread has read the new tiles. The tile
// reads are gated by the test, so "not resident yet" is certain, not a race.

#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "render/test/lod_view_checks.h"
#include "terrain/height_pyramid.h"
#include "terrain/height_tile_cache.h"
#include "terrain/paged_heights.h"

namespace {

using ig::terrain::HeightPyramid;
using ig::terrain::HeightTileCache;

// Background reads wait while the gate is closed; reads on the test's
// (frame) thread are counted and never wait.
struct Gate {
  std::mutex mutex;
  std::condition_variable opened;
  bool open = true;
  std::thread::id frame_thread = std::this_thread::get_id();
  std::atomic<int> frame_thread_reads{0};

  void set(bool o) {
    {
      std::lock_guard lock(mutex);
      open = o;
    }
    opened.notify_all();
  }
  void pass() {
    if (std::this_thread::get_id() == frame_thread) {
      ++frame_thread_reads;
      return;
    }
    std::unique_lock lock(mutex);
    opened.wait(lock, [&] { return open; });
  }
};

// `whole`'s heights served through a tile cache of 64^2 tiles behind `gate`,
// with the overview and pyramid the paged loader would build.
ig::terrain::Heightfield paged_copy(const ig::terrain::Heightfield& whole, Gate& gate) {
  const int w = whole.width, h = whole.height;
  auto cache = std::make_shared<HeightTileCache>(
      w, h, 64, std::size_t(64) << 20, [&whole, &gate](int, int, int x0, int y0, int tw, int th, float* out) {
        gate.pass();
        for (int r = 0; r < th; ++r)
          for (int c = 0; c < tw; ++c) out[std::size_t(r) * tw + c] = whole.at(x0 + c, y0 + r);
      });
  const HeightPyramid pyramid(whole);
  std::vector<HeightPyramid::MinMax> level2;
  for (int j = 0; j < pyramid.level_height(2); ++j)
    for (int i = 0; i < pyramid.level_width(2); ++i) level2.push_back(pyramid.node(2, i, j));
  auto paged = std::make_shared<ig::terrain::PagedHeights>();
  paged->cache = cache;
  paged->overview = std::make_shared<ig::terrain::Heightfield>(whole);
  paged->pyramid = std::make_shared<const HeightPyramid>(HeightPyramid::from_level2(w, h, cache, level2, pyramid.root()));
  ig::terrain::Heightfield hf = whole;
  hf.heights.clear();
  hf.paged = paged;
  return hf;
}

TEST(PagedLevel1Hold, AFarJumpKeepsLevel1UntilItsTilesAreIn) {
  lod_views::World world(1025);
  Gate gate;
  const ig::terrain::Heightfield hf = paged_copy(world.hf, gate);
  ig::render::TerrainScene scene(hf, ig::render::ShadingParams{});
  scene.enable_height_window(256);
  ig::render::TwoLevelMethod method(scene, world.shader_dir);
  method.set_viewport(lod_views::kW, lod_views::kH);
  const HeightTileCache& cache = *hf.paged->cache;
  struct OpenAtExit {  // the cache's thread must finish its read before the cache goes
    Gate& g;
    ~OpenAtExit() { g.set(true); }
  } open_at_exit{gate};

  // Looking down steeply: E, Level1 and the window near the eye.
  const double s = world.hf.spacing_x_m;
  const auto here = lod_views::camera_at(world.hf, 200 * s, 200 * s, 300.0, 45.0, -60.0);
  const auto there = lod_views::camera_at(world.hf, 820 * s, 830 * s, 300.0, 45.0, -60.0);
  scene.apply(method.update(here));  // the first frame may wait: nothing is resident yet
  cache.wait_idle();
  scene.apply(method.update(here));
  cache.wait_idle();
  ASSERT_FALSE(method.level1_held());
  const glm::ivec2 origin_here = method.level1_origin();
  const int n_here = method.level1_size();
  EXPECT_LT(std::abs(origin_here.x + n_here / 2 - 200), n_here);
  const auto before = cache.stats();
  gate.frame_thread_reads = 0;

  // The jump, with the background reads held back: several frames, none
  // reads a tile on the frame's thread and Level1 stays where it was.
  gate.set(false);
  for (int frame = 0; frame < 3; ++frame) {
    scene.apply(method.update(there));
    EXPECT_TRUE(method.level1_held()) << "frame " << frame;
    EXPECT_EQ(method.level1_origin(), origin_here);
    EXPECT_EQ(method.level1_size(), n_here);
  }
  EXPECT_EQ(gate.frame_thread_reads, 0);
  EXPECT_EQ(cache.stats().misses, before.misses);
  EXPECT_GT(cache.stats().deferred, before.deferred);

  // Reads let through: within a few frames Level1 is on the new view.
  gate.set(true);
  int frames = 0;
  while (method.level1_held() && frames < 200) {
    cache.wait_idle();
    scene.apply(method.update(there));
    ++frames;
  }
  EXPECT_FALSE(method.level1_held()) << "after " << frames << " frames";
  const glm::ivec2 centre = method.level1_origin() + method.level1_size() / 2;
  EXPECT_LT(std::abs(centre.x - 820) + std::abs(centre.y - 830), method.level1_size()) << centre.x << "," << centre.y;
  EXPECT_EQ(gate.frame_thread_reads, 0);
  EXPECT_EQ(cache.stats().misses, before.misses) << "a frame waited on a tile";
  std::printf("far jump: Level1 held until the tiles were in, %d frames after the reads were let through\n", frames);
}

}  // namespace
