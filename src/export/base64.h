#pragma once
// Base64 (RFC 4648, with padding): VTU's inline binary arrays and the web page's inlined
// model and scripts.

#include <string>
#include <string_view>

namespace systole::exporter {

std::string base64(std::string_view bytes);

}  // namespace systole::exporter
