#pragma once
// Base64 (RFC 4648, standard alphabet, with padding): VTU's inline binary arrays (written by
// export/vtk.h, read back by mesh/vtu_read.h) and the export page's inlined model and scripts.
// In common/ because both sides use it: mesh/ reads what export/ writes, and mesh/ may not
// include export/.

#include <optional>
#include <string>
#include <string_view>

namespace systole {

/// `bytes` as base64 text, padded to whole groups of four characters.
std::string base64(std::string_view bytes);

/// The bytes base64 `text` encodes; nullopt when it holds a character outside the alphabet,
/// a misplaced '=' or a group cut short. ASCII whitespace anywhere is skipped (VTK breaks
/// long arrays into lines), and a padded group may be followed by another: several encoded
/// streams one after the other decode to their bytes joined (VTK writers may encode an
/// array's byte-count header and its data as two streams).
std::optional<std::string> base64_decode(std::string_view text);

}  // namespace systole
