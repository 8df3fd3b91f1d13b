#pragma once
// The end of one frame's GL work, as a fence in the command stream: for
// running frames pipelined (issued while earlier ones are still being drawn,
// as a live IG with frames in flight does), where waiting is for one frame
// to be done instead of glFinish after each stage.

namespace ig::gl {

class FrameFence {
 public:
  FrameFence() = default;
  FrameFence(const FrameFence&) = delete;
  FrameFence& operator=(const FrameFence&) = delete;
  FrameFence(FrameFence&& o) noexcept : sync_(o.sync_) { o.sync_ = nullptr; }
  FrameFence& operator=(FrameFence&& o) noexcept;
  ~FrameFence();

  // Fences everything issued so far and flushes it to the driver.
  static FrameFence after_issued_work();
  // Whether the work before the fence is done (an empty fence is); never waits.
  bool done() const;
  // Waits until the work before the fence is done.
  void wait() const;

 private:
  void* sync_ = nullptr;  // GLsync: GL types stay in the .cpp
};

}  // namespace ig::gl
