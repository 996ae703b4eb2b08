#pragma once
// Small helpers shared by the libav* code in encode/ (internal; not part of the API).

#include <string>

namespace systole::encode::detail {

/// The text libav gives for an AVERROR code, e.g. "No such file or directory".
std::string av_error_text(int averror);

/// Lowers libav's log level to AV_LOG_ERROR (libx264's banner and statistics go through
/// av_log) unless the process already chose a quieter level.
void quiet_libav_logging();

}  // namespace systole::encode::detail
