#include "gl/work_counters.h"

#include <stdexcept>

#include "stats/timing.h"

namespace ig::gl {
namespace {
constexpr std::array<GLenum, 4> kTargets = {GL_VERTEX_SHADER_INVOCATIONS, GL_FRAGMENT_SHADER_INVOCATIONS,
                                            GL_PRIMITIVES_SUBMITTED, GL_SAMPLES_PASSED};
int queries_of(bool count_samples) { return count_samples ? 4 : 3; }
}  // namespace

WorkTally& work_tally() {
  thread_local WorkTally tally;
  return tally;
}

bool PassRecorder::supported() {
  return epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query");
}

PassRecorder::PassRecorder(std::vector<std::string> pass_names)
    : names_(std::move(pass_names)), supported_(supported()) {}

void PassRecorder::begin_frame() {
  if (active_) end();
  used_ = 0;
}

void PassRecorder::begin(std::string_view pass, bool count_samples) {
  if (active_) end();
  int index = -1;
  for (size_t k = 0; k < names_.size(); ++k)
    if (names_[k] == pass) index = int(k);
  if (index < 0) throw std::logic_error("PassRecorder: pass '" + std::string(pass) + "' was not declared");
  if (used_ == int(segments_.size())) {
    segments_.emplace_back();
    if (supported_)
      for (auto& q : segments_.back().queries) q = create_query();
  }
  Segment& s = segments_[used_];
  s.pass = index;
  s.count_samples = count_samples;
  s.tally_at_begin = work_tally();
  s.ms = 0.0;
  if (timed_) {
    glFinish();
    s.start = stats::WallClock::now();
  }
  s.queried = supported_ && queries_;
  if (s.queried)
    for (int q = 0; q < queries_of(count_samples); ++q) glBeginQuery(kTargets[q], s.queries[q].id());
  active_ = true;
}

void PassRecorder::end() {
  if (!active_) return;
  Segment& s = segments_[used_];
  if (s.queried)
    for (int q = 0; q < queries_of(s.count_samples); ++q) glEndQuery(kTargets[q]);
  s.tally_at_end = work_tally();
  if (timed_) {
    glFinish();
    s.ms = stats::ms_since(s.start);
  }
  ++used_;
  active_ = false;
}

std::vector<PassWork> PassRecorder::read() {
  if (active_) end();
  std::vector<PassWork> out(names_.size());
  for (size_t k = 0; k < names_.size(); ++k) {
    out[k].name = names_[k];
    if (timed_) out[k].ms = 0.0;
  }
  for (int k = 0; k < used_; ++k) {
    const Segment& s = segments_[k];
    PassWork& w = out[s.pass];
    if (s.queried) {
      GLuint64 v[4] = {0, 0, 0, 0};
      for (int q = 0; q < queries_of(s.count_samples); ++q)
        glGetQueryObjectui64v(s.queries[q].id(), GL_QUERY_RESULT, &v[q]);
      w.vs_invocations += v[0];
      w.fs_invocations += v[1];
      w.primitives += v[2];
      w.samples_passed += v[3];
    }
    if (timed_) w.ms += s.ms;
    w.draw_calls += s.tally_at_end.draw_calls - s.tally_at_begin.draw_calls;
    w.bytes_uploaded += s.tally_at_end.bytes_uploaded - s.tally_at_begin.bytes_uploaded;
  }
  return out;
}

}  // namespace ig::gl
