#pragma once
// The fixture of the image tests of the baselines with precomputed pieces
// (geomipmap_test, chunked_test, cdlod_test): lod_views::ReferenceFramesTest
// for one method, made from a scene, the shader folder and its knob, with
// the checks those tests run on it.

#include <memory>
#include <string>

#include "render/test/lod_view_checks.h"

namespace lod_views {

template <class Method>
class MethodFramesTest : public ReferenceFramesTest {
 protected:
  // The method on the world's scene at `knob`.
  static Method make(double knob) { return Method(*world_->scene, world_->shader_dir, knob); }

  // The method at `knob` on any scene (expect_odd_sized_dems_render_without_holes).
  static MakeMethod maker(double knob) {
    return [knob](const ig::render::TerrainScene& scene) {
      return std::make_unique<Method>(scene, world_->shader_dir, knob);
    };
  }

  // lod_views::expect_every_view_without_holes of the method at `knob`.
  template <class Each>
  static void expect_every_view_without_holes(double knob, const std::string& name, Each each) {
    Method method = make(knob);
    lod_views::expect_every_view_without_holes(*world_, *reference_, method, name, each);
  }

  // The registry's knob sweep of `name` at the first two views, the method
  // made afresh at each setting: every frame, after `each(view, knob, frame,
  // method)` (the method's own figures and checks), goes to SweepChecks.
  template <class Each>
  static void expect_knob_sweep(const std::string& name, const std::string& knob_label, Each each) {
    const auto all = views(world_->hf);
    for (const auto& v : {all[0], all[1]}) {
      SweepChecks sweep(v.name, knob_label);
      for (double knob : ig::render::knob_sweep(name)) {
        Method method = make(knob);
        const Frame f = render(*world_, method, v.camera);
        each(v, knob, f, method);
        sweep.add(f, knob);
      }
      sweep.finish();
    }
  }
};

}  // namespace lod_views
