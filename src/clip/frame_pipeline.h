#pragma once
// Three stages over a clip's frames - produce (simulate), render, consume (encode) - each
// on its own thread, handing frames on through a ring of `depth` slots per hand-over, so
// frame n+1 simulates while frame n renders and frame n-1 encodes. Nothing is allocated
// per frame: frame n uses slot n % depth. Each stage sees the frames in order and alone,
// so the result is the same as running the three one after another for every frame
// (`overlap` false), whatever the timing. The render stage runs on the calling thread:
// an OpenGL context belongs to the thread that made it current.

#include <functional>

namespace systole::clip {

struct PipelineStages {
  /// Frame `index` (0, 1, ... count-1) into hand-over slot `slot`.
  std::function<void(int index, int slot)> produce;
  /// Reads produce's slot `slot` and fills its own slot `slot`.
  std::function<void(int index, int slot)> render;
  /// Reads render's slot `slot`.
  std::function<void(int index, int slot)> consume;
};

/// Runs `count` frames through the stages. With `overlap`, produce and consume run on
/// threads of their own. The first exception any stage throws stops every stage (frames
/// already under way finish their current step) and is rethrown here.
void run_frame_pipeline(int count, int depth, bool overlap, const PipelineStages& stages);

}  // namespace systole::clip
