#pragma once
// One persistent thread that runs a job beside the caller, for splitting a
// frame's CPU work in two while the renderer's own threads are idle (after
// the frame's glFinish): run() hands it the job, wait() returns when it is
// done. A thread started per frame would cost tens of microseconds.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace ig::session {

class SideWorker {
 public:
  SideWorker();
  ~SideWorker();
  SideWorker(const SideWorker&) = delete;
  SideWorker& operator=(const SideWorker&) = delete;

  // Starts `job` on the worker; the previous one must have been waited for.
  void run(std::function<void()> job);
  // Blocks until the job given to run() has returned.
  void wait();

 private:
  void loop();
  std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> job_;
  bool busy_ = false, stop_ = false;
  std::thread thread_;
};

}  // namespace ig::session
