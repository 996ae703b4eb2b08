#include "common/warning.h"

#include <iostream>
#include <mutex>
#include <utility>

namespace systole {
namespace {

std::mutex g_mutex;
std::function<void(const std::string&)> g_listener;

}  // namespace

void warn(const std::string& text) {
  const std::lock_guard guard(g_mutex);
  if (g_listener) {
    g_listener(text);
    return;
  }
  std::cerr << "systole: warning: " + text + "\n" << std::flush;
}

std::function<void(const std::string&)> set_warning_listener(std::function<void(const std::string&)> listener) {
  const std::lock_guard guard(g_mutex);
  return std::exchange(g_listener, std::move(listener));
}

}  // namespace systole
