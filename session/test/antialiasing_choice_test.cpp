// render.antialiasing "auto": multisampling on a GPU, the post filter on a
// CPU rasterizer; an explicit choice is kept as it is (no GL needed).
#include <gtest/gtest.h>

#include "session/scenario_runner.h"

using ig::session::resolve_antialiasing;

TEST(AntialiasingChoice, AutoPicksThePostFilterOnCpuRasterizers) {
  EXPECT_EQ(resolve_antialiasing("auto", "llvmpipe (LLVM 15.0.6, 256 bits)"), "fxaa");
  EXPECT_EQ(resolve_antialiasing("auto", "softpipe"), "fxaa");
  EXPECT_EQ(resolve_antialiasing("auto", "NVIDIA H100 80GB HBM3/PCIe/SSE2"), "msaa");
  EXPECT_EQ(resolve_antialiasing("auto", "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)"), "msaa");
}

TEST(AntialiasingChoice, ExplicitChoicesAreKept) {
  for (const char* mode : {"msaa", "fxaa", "off"}) {
    EXPECT_EQ(resolve_antialiasing(mode, "llvmpipe"), mode);
    EXPECT_EQ(resolve_antialiasing(mode, "NVIDIA"), mode);
  }
}
