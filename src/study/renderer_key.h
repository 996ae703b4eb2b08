#pragma once
// The name golden images are filed under: software rasterizers differ across versions, so
// references are only comparable within one key. See docs/golden-images.md.

#include <string>

#include "render/renderer.h"

namespace systole::study {

/// "llvmpipe-mesa-22.3.6-llvm-15.0.6" from renderer "llvmpipe (LLVM 15.0.6, 256 bits)" and
/// version "4.5 (Core Profile) Mesa 22.3.6": the driver, the Mesa version, then what the
/// renderer string says in parentheses except the SIMD width (llvmpipe gives the same
/// pixels at 128 and 256 bits; measured). Lower case, [a-z0-9.] and single dashes only.
std::string renderer_key(const render::GlInfo& gl);

}  // namespace systole::study
