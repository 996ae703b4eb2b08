#pragma once
// What `systole info` prints: versions, the GL renderer, the encoders.

#include <string>

namespace systole::study {

/// Creates a small off-screen context to ask the GL driver; throws if it cannot.
std::string system_info();

}  // namespace systole::study
