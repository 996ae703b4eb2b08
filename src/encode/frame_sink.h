#pragma once
// Where rendered frames go: an MP4 video, a folder of PNGs, ... One interface, so the
// frame loop does not care.

#include "common/image.h"

namespace systole::encode {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  /// Takes frame number `frame_index` of the clip. Frames arrive in increasing order.
  virtual void write(const Image& image, int frame_index) = 0;
  /// Completes the output (flush, trailer) and moves it into place. Without finish() -
  /// an error or an interrupt - the sink's destructor leaves earlier output untouched.
  virtual void finish() = 0;
};

}  // namespace systole::encode
