#pragma once
// `man systole`: one roff page with a section per subcommand, written from the same walk of
// the CLI11 app as the shell completions (reference.h), so it lists exactly what --help does.

#include <string>

#include "cli/manual/reference.h"

namespace systole::cli::manual {

/// What the page says that the CLI11 app does not hold.
struct PageContext {
  std::string summary;     ///< The NAME line after "systole \-" (cli::kSummary).
  std::string date;        ///< The title line's date, the release's ("26 Nov 2026"): same sources, same page.
  std::string scenes_dir;  ///< Where the example scenes are installed: "/usr/share/systole/scenes".
  std::string docs_dir;    ///< Where the documentation is installed: "/usr/share/doc/systole".
};

/// The page in man(7) roff.
std::string man_page(const AppReference& app, const PageContext& context);

/// Text escaped for roff: backslashes, minus signs, and a leading '.' or '\'' that would be
/// read as a request.
std::string roff_escape(const std::string& text);

}  // namespace systole::cli::manual
