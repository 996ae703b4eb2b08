#include "encode/av_error.h"

extern "C" {
#include <libavutil/error.h>
#include <libavutil/log.h>
}

namespace systole::encode::detail {

std::string av_error_text(int averror) {
  char buffer[AV_ERROR_MAX_STRING_SIZE] = {};
  if (av_strerror(averror, buffer, sizeof buffer) < 0) {
    return "libav error " + std::to_string(averror);
  }
  return buffer;
}

void quiet_libav_logging() {
  if (av_log_get_level() > AV_LOG_ERROR) av_log_set_level(AV_LOG_ERROR);
}

}  // namespace systole::encode::detail
