// libav's error texts and log level (encode/av_error.h).

#include "encode/av_error.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>

extern "C" {
#include <libavutil/error.h>
#include <libavutil/log.h>
}

namespace systole::encode::detail {
namespace {

TEST(AvError, AnErrnoCodeReadsAsTheSystemsText) {
  EXPECT_EQ(av_error_text(AVERROR(ENOENT)), std::strerror(ENOENT));
  EXPECT_EQ(av_error_text(AVERROR(ENOMEM)), std::strerror(ENOMEM));
}

TEST(AvError, LibavsOwnCodesHaveTheirOwnText) {
  EXPECT_EQ(av_error_text(AVERROR_EOF), "End of file");
  EXPECT_EQ(av_error_text(AVERROR_ENCODER_NOT_FOUND), "Encoder not found");
}

TEST(AvError, QuietLoggingLowersOnlyALouderLevel) {
  const int before = av_log_get_level();
  av_log_set_level(AV_LOG_DEBUG);
  quiet_libav_logging();
  EXPECT_EQ(av_log_get_level(), AV_LOG_ERROR);
  av_log_set_level(AV_LOG_QUIET);
  quiet_libav_logging();
  EXPECT_EQ(av_log_get_level(), AV_LOG_QUIET);  // The process chose quieter: kept.
  av_log_set_level(before);
}

}  // namespace
}  // namespace systole::encode::detail
