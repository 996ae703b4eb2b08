// `man systole` and the shell completions are written from the CLI11 definitions that
// `--help` prints (src/cli/manual/): the page must list exactly the options --help lists,
// command by command, and the bash completion must complete what a user types.

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <vector>

#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const fs::path kManPage = fs::path(SYSTOLE_MANUAL_DIR) / "man" / "systole.1";
const fs::path kBashCompletion = fs::path(SYSTOLE_MANUAL_DIR) / "completion" / "systole";
const fs::path kZshCompletion = fs::path(SYSTOLE_MANUAL_DIR) / "completion" / "_systole";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The lines of one section of CLI11's help ("Options:", "Subcommands:") up to the next heading.
std::vector<std::string> help_section(const std::string& help, const std::string& heading) {
  std::vector<std::string> out;
  bool inside = false;
  for (const auto& line : lines_of(help)) {
    if (!line.empty() && line[0] != ' ') {
      inside = line == heading;
      continue;
    }
    if (inside) out.push_back(line);
  }
  return out;
}

/// The option names CLI11's --help lists: "  -o,--output FILE   Video ..." gives -o and --output.
/// A description wrapped onto a following line is indented further, so only lines that start
/// with two spaces and a dash name options.
std::set<std::string> help_options(const std::string& help) {
  std::set<std::string> names;
  for (const auto& line : help_section(help, "Options:")) {
    if (line.rfind("  -", 0) != 0) continue;
    std::string first = line.substr(2, line.find(' ', 2) - 2);
    std::istringstream parts(first);
    for (std::string name; std::getline(parts, name, ',');) names.insert(name);
  }
  return names;
}

/// The subcommands `systole --help` lists.
std::vector<std::string> help_commands(const std::string& help) {
  std::vector<std::string> commands;
  for (const auto& line : help_section(help, "Subcommands:")) {
    if (line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ') commands.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return commands;
}

/// Roff to plain text: \- is a minus sign, \fB \fI \fR switch fonts, \& is zero-width.
std::string unroff(std::string text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size()) {
      const char next = text[i + 1];
      if (next == '-') out += '-';
      if (next == 'e') out += '\\';
      i += next == 'f' ? 2 : 1;
      continue;
    }
    out += text[i];
  }
  return out;
}

/// The options a section of the man page describes: the tag line after each .TP, whose
/// dash-words are the option's names ("-o, --output FILE").
std::set<std::string> man_section_options(const std::string& page, const std::string& section_heading) {
  std::set<std::string> names;
  const auto lines = lines_of(page);
  bool inside = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind(".SH ", 0) == 0) inside = lines[i] == section_heading;
    if (!inside || lines[i] != ".TP" || i + 1 >= lines.size()) continue;
    std::istringstream words(unroff(lines[i + 1]));
    for (std::string word; words >> word;) {
      if (word.back() == ',') word.pop_back();
      if (word.size() > 1 && word[0] == '-') names.insert(word);
    }
  }
  return names;
}

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += n + " ";
  return out;
}

TEST(Manual, ManPageListsEveryOptionHelpPrintsForEveryCommand) {
  ASSERT_TRUE(fs::exists(kManPage)) << kManPage << " was not generated";
  const std::string page = read_file(kManPage);
  const auto top = run(systole() + " --help");
  ASSERT_EQ(top.exit_code, 0) << top.output;
  const auto commands = help_commands(top.output);
  // The parse of --help itself is checked, or two empty sets would agree.
  ASSERT_GE(commands.size(), 8u) << top.output;
  EXPECT_EQ(help_options(top.output), man_section_options(page, ".SH OPTIONS"));

  for (const auto& command : commands) {
    SCOPED_TRACE(command);
    const auto help = run(systole() + " " + command + " --help");
    ASSERT_EQ(help.exit_code, 0) << help.output;
    const auto listed = help_options(help.output);
    ASSERT_TRUE(listed.count("--help")) << help.output;
    const auto described = man_section_options(page, ".SH \"systole " + command + "\"");
    EXPECT_EQ(listed, described) << "--help lists: " << joined(listed) << "\nman page has: " << joined(described);
  }
}

TEST(Manual, ManPageShowsRenderOptionsWithTheirValues) {
  const std::string page = unroff(read_file(kManPage));
  for (const char* text : {"-o, --output FILE", "--png DIR", "-D, --define KEY=VALUE", "--no-video",
                           "one of auto, none, json", ".TH SYSTOLE 1", "EXIT STATUS", "/scenes"}) {
    EXPECT_NE(page.find(text), std::string::npos) << "missing '" << text << "'";
  }
}

/// What the bash completion offers for `words` (the last one being completed) in `folder`.
std::set<std::string> bash_complete(const std::vector<std::string>& words, const fs::path& folder) {
  // A driver folder per test: ctest runs the completion tests at once, and one's scratch()
  // would empty the folder the other is writing to.
  const auto dir = scratch(std::string("bash_complete_driver_") +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
  const auto driver = dir / "complete.sh";
  write_file(driver,
             "source \"$1\" || exit 2\ncd \"$2\" || exit 2\nshift 2\n"
             "COMP_WORDS=(\"$@\"); COMP_CWORD=$(( $# - 1 )); COMP_LINE=\"$*\"; COMP_POINT=${#COMP_LINE}\n"
             "_systole\nprintf '%s\\n' \"${COMPREPLY[@]}\"\n");
  std::string command = "bash --norc --noprofile " + driver.string() + " '" + kBashCompletion.string() + "' '" +
                        folder.string() + "'";
  for (const auto& w : words) command += " '" + w + "'";
  const auto r = run(command);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::set<std::string> replies;
  for (const auto& line : lines_of(r.output)) {
    if (!line.empty()) replies.insert(line);
  }
  return replies;
}

bool have_bash() { return run("bash --norc --noprofile -c true").exit_code == 0; }

TEST(Manual, BashCompletesCommandsOptionsAndChoices) {
  if (!have_bash()) GTEST_SKIP() << "bash is not installed: the bash completion cannot be driven";
  ASSERT_TRUE(fs::exists(kBashCompletion)) << kBashCompletion << " was not generated";
  const auto here = scratch("bash_complete_words");
  EXPECT_EQ(bash_complete({"systole", "re"}, here), std::set<std::string>{"render"});
  EXPECT_EQ(bash_complete({"systole", "render", "--n"}, here), std::set<std::string>{"--no-video"});
  EXPECT_EQ(bash_complete({"systole", "render", "--progress", ""}, here),
            (std::set<std::string>{"auto", "none", "json"}));
  // --progress=j: bash splits the word at '='.
  EXPECT_EQ(bash_complete({"systole", "render", "--progress", "=", "j"}, here), std::set<std::string>{"json"});
  EXPECT_EQ(bash_complete({"systole", "validate", "-D", "output.wid"}, here), std::set<std::string>{"output.width="});
  EXPECT_EQ(bash_complete({"systole", "tune", "-D", "output.wid"}, here), std::set<std::string>{"output.width="});
  EXPECT_EQ(bash_complete({"systole", "compare", "--max-d"}, here), std::set<std::string>{"--max-delta"});
}

TEST(Manual, BashCompletesAPartialScenePathToYamlFiles) {
  if (!have_bash()) GTEST_SKIP() << "bash is not installed: the bash completion cannot be driven";
  const auto dir = scratch("bash_complete_scenes");
  write_file(dir / "heart.yaml", "organs: []\n");
  write_file(dir / "heart-notes.txt", "not a scene\n");
  write_file(dir / "lungs.yml", "organs: []\n");
  EXPECT_EQ(bash_complete({"systole", "render", "hea"}, dir), std::set<std::string>{"heart.yaml"});
  EXPECT_EQ(bash_complete({"systole", "validate", "lu"}, dir), std::set<std::string>{"lungs.yml"});
  // The shipped scenes, by a path through their folder.
  const std::string scenes = source("scenes");
  EXPECT_EQ(bash_complete({"systole", "render", scenes + "/heart-cu"}, dir),
            std::set<std::string>{scenes + "/heart-cutaway.yaml"});
  // Where a file goes (compare's images), any file is offered.
  EXPECT_EQ(bash_complete({"systole", "compare", "heart-n"}, dir), std::set<std::string>{"heart-notes.txt"});
}

TEST(Manual, ZshCompletionParses) {
  if (run("zsh -fc true").exit_code != 0) GTEST_SKIP() << "zsh is not installed: the zsh completion is not checked";
  ASSERT_TRUE(fs::exists(kZshCompletion)) << kZshCompletion << " was not generated";
  const auto r = run("zsh -fn " + kZshCompletion.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

}  // namespace
}  // namespace systole::test
