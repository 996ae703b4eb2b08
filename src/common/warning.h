#pragma once
// Warnings: what a run notices that does not stop it but that a user should hear of (a mesh
// file cut short, a scene in which nothing can move). One line each on stderr, from any
// module, as "systole: warning: <text>"; the run goes on and its exit code is unchanged.

#include <functional>
#include <string>

namespace systole {

/// Prints `text` as a warning (thread-safe: one whole line at a time).
void warn(const std::string& text);

/// Routes warnings to `listener` instead of stderr while it is set (tests, a batch that
/// collects them); an empty function restores stderr. Returns the previous listener.
std::function<void(const std::string&)> set_warning_listener(std::function<void(const std::string&)> listener);

}  // namespace systole
