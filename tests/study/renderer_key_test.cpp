// The key golden images are filed under.

#include "study/renderer_key.h"

#include <gtest/gtest.h>

namespace systole::study {
namespace {

TEST(RendererKey, DriverMesaAndLlvmVersions) {
  EXPECT_EQ(renderer_key({"Mesa/X.org", "llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6", "4.50"}),
            "llvmpipe-mesa-22.3.6-llvm-15.0.6");
  EXPECT_EQ(renderer_key({"Mesa", "llvmpipe (LLVM 16.0.6, 256 bits)", "4.5 (Core Profile) Mesa 23.1.0", "4.50"}),
            "llvmpipe-mesa-23.1.0-llvm-16.0.6");
  EXPECT_EQ(renderer_key({"Mesa", "softpipe", "3.3 (Core Profile) Mesa 20.0.0", "3.30"}), "softpipe-mesa-20.0.0");
}

TEST(RendererKey, TheVectorWidthIsNotPartOfIt) {
  // llvmpipe renders the same pixels at 128 and 256 bits (LP_NATIVE_VECTOR_WIDTH=128, measured).
  EXPECT_EQ(renderer_key({"Mesa", "llvmpipe (LLVM 15.0.6, 128 bits)", "4.5 (Core Profile) Mesa 22.3.6", "4.50"}),
            renderer_key({"Mesa", "llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6", "4.50"}));
}

TEST(RendererKey, AnyRendererGivesAFileName) {
  EXPECT_EQ(renderer_key({"NVIDIA Corporation", "NVIDIA GeForce RTX 3060/PCIe/SSE2", "4.6.0 NVIDIA 535.54", "4.60"}),
            "nvidia-geforce-rtx-3060-pcie-sse2-4.6.0-nvidia-535.54");
}

}  // namespace
}  // namespace systole::study
