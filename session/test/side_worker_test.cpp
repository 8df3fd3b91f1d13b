// The side worker runs each job handed to it exactly once, beside the
// caller, and wait() returns only after the job is done.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "session/side_worker.h"

namespace {

TEST(SideWorker, EveryJobRunsOnceOnAnotherThreadBeforeWaitReturns) {
  ig::session::SideWorker worker;
  std::vector<int> done(1000, 0);
  const auto caller = std::this_thread::get_id();
  std::atomic<int> on_caller{0};
  for (int k = 0; k < 1000; ++k) {
    worker.run([&, k] {
      done[k] += 1;
      if (std::this_thread::get_id() == caller) ++on_caller;
    });
    worker.wait();
    ASSERT_EQ(done[k], 1) << k;  // finished before wait() returned
  }
  EXPECT_EQ(on_caller.load(), 0);
}

TEST(SideWorker, StopsCleanlyWithOrWithoutWork) {
  { ig::session::SideWorker idle; }
  int ran = 0;
  {
    ig::session::SideWorker worker;
    worker.run([&] { ran = 1; });
    worker.wait();
  }
  EXPECT_EQ(ran, 1);
}

}  // namespace
