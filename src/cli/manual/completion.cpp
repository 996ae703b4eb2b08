#include "cli/manual/completion.h"

#include <cctype>
#include <sstream>

#include "common/error.h"

namespace systole::cli::manual {
namespace {

/// Words go into the scripts inside single quotes, split at spaces: an option name, a choice
/// or a scene key with a quote or a space would break them, so the build stops instead.
const std::string& shell_word(const std::string& word) {
  if (word.empty() || word.find_first_of("' \t\n\\") != std::string::npos) {
    throw Error(ExitCode::kInternal, "cannot write '" + word + "' into a completion word list");
  }
  return word;
}

std::string word_list(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + shell_word(w);
  return out;
}

/// The first clause of a description, for a completion menu ("Video to write: .mp4 ..." gives
/// "Video to write"); quotes and brackets, which zsh's _arguments specs use, become harmless.
std::string menu_text(const std::string& description) {
  std::string text = description;
  for (const char* end : {". ", ": ", "; "}) text = text.substr(0, text.find(end));
  if (!text.empty() && text.back() == '.') text.pop_back();
  std::string out;
  for (const char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else if (c == '[' || c == '(' || c == '{') {
      out += '(';
    } else if (c == ']' || c == ')' || c == '}') {
      out += ')';
    } else if (c == ':' || c == '\\' || c == '`' || c == '$') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::vector<std::string> all_names(const std::vector<OptionReference>& options) {
  std::vector<std::string> names;
  for (const auto& o : options) names.insert(names.end(), o.names.begin(), o.names.end());
  return names;
}

/// The kind the bash helper _systole_value completes: scene, file, folder or key.
std::string bash_kind(ValueKind kind) {
  switch (kind) {
    case ValueKind::kScene: return "scene";
    case ValueKind::kFile: return "file";
    case ValueKind::kFolder: return "folder";
    case ValueKind::kSceneKey: return "key";
    default: return "";
  }
}

/// The `case $prev in` arm of one option that takes a value.
std::string bash_value_arm(const OptionReference& o) {
  std::string names;
  for (const auto& n : o.names) names += (names.empty() ? "" : "|") + shell_word(n);
  std::string action;
  if (!o.choices.empty()) {
    action = "COMPREPLY=($(compgen -W '" + word_list(o.choices) + "' -- \"$cur\"))";
  } else if (const std::string kind = bash_kind(o.kind); !kind.empty()) {
    action = "_systole_value " + kind + " \"$cur\"";
  } else {
    action = ":";  // a number or a list: nothing to offer, and no file names either
  }
  return "        " + names + ") " + action + "; return ;;\n";
}

void write_bash_command(std::ostream& out, const CommandReference& c) {
  out << "    " << shell_word(c.name) << ")\n      case $prev in\n";
  for (const auto& o : c.options) {
    if (!o.flag()) out << bash_value_arm(o);
  }
  out << "      esac\n"
      << "      if [[ $cur == -* ]]; then\n"
      << "        COMPREPLY=($(compgen -W '" << word_list(all_names(c.options)) << "' -- \"$cur\"))\n"
      << "        return\n      fi\n";
  // Every positional of a command is of one kind today (compare's two PNGs are both files).
  const std::string kind = c.positionals.empty() ? "" : bash_kind(c.positionals.front().kind);
  if (!kind.empty()) out << "      _systole_value " << kind << " \"$cur\"\n";
  out << "      ;;\n";
}

std::string zsh_action(const OptionReference& o) {
  if (!o.choices.empty()) return "(" + word_list(o.choices) + ")";
  switch (o.kind) {
    case ValueKind::kScene: return "_files -g \"*.(yaml|yml)(-.)\"";
    case ValueKind::kFile: return "_files";
    case ValueKind::kFolder: return "_files -/";
    case ValueKind::kSceneKey: return "_systole_scene_keys";
    default: return " ";
  }
}

std::string zsh_message(const OptionReference& o) {
  std::string message = o.positional() ? o.positional_name : o.value_name;
  for (char& c : message) c = c == ':' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return message;
}

/// One _arguments spec: '(-o --output)'{-o,--output}'[Video to write]:file:_files'.
std::string zsh_option_spec(const OptionReference& o) {
  std::string names;
  for (const auto& n : o.names) names += (names.empty() ? "" : ",") + shell_word(n);
  std::string exclusion;
  if (o.repeatable) {
    exclusion = "'*'";
  } else {
    std::string list;
    for (const auto& n : o.names) list += (list.empty() ? "" : " ") + n;
    exclusion = "'(" + list + ")'";
  }
  std::string spec = exclusion + (o.names.size() > 1 ? "{" + names + "}" : names) + "'[" + menu_text(o.description) + "]";
  if (!o.flag()) spec += ":" + zsh_message(o) + ":" + zsh_action(o);
  return spec + "'";
}

void write_zsh_command(std::ostream& out, const CommandReference& c) {
  out << "        " << shell_word(c.name) << ")\n          _arguments -s";
  for (const auto& o : c.options) out << " \\\n            " << zsh_option_spec(o);
  for (std::size_t i = 0; i < c.positionals.size(); ++i) {
    const auto& p = c.positionals[i];
    const std::string position = p.repeatable ? "*" : std::to_string(i + 1);
    out << " \\\n            '" << position << ":" << zsh_message(p) << ":" << zsh_action(p) << "'";
  }
  out << " && ret=0\n          ;;\n";
}

/// Scene keys that name one value (no list in their path: a list item goes by its index or
/// name, `organs.heart.mesh.detail`, which no fixed list knows).
std::vector<std::string> completable_keys(const std::vector<std::string>& scene_keys) {
  std::vector<std::string> keys;
  for (const auto& k : scene_keys) {
    if (k.find("[]") == std::string::npos) keys.push_back(k);
  }
  return keys;
}

}  // namespace

std::string bash_completion(const AppReference& app, const std::vector<std::string>& scene_keys) {
  std::ostringstream out;
  out << "# bash completion for systole                                  -*- shell-script -*-\n"
      << "# Generated by systole-manual from the command line's own definitions (src/cli/); do not edit.\n\n"
      << "_systole_scene_keys='" << word_list(completable_keys(scene_keys)) << "'\n\n"
      << R"(# _systole_value KIND WORD: scene (YAML files and folders), file, folder, or key (-D's scene keys).
_systole_value() {
  local IFS=$'\n'
  case $1 in
    scene)
      compopt -o filenames 2>/dev/null
      COMPREPLY=($(compgen -d -- "$2") $(compgen -f -X '!*.yaml' -- "$2") $(compgen -f -X '!*.yml' -- "$2")) ;;
    file)
      compopt -o filenames 2>/dev/null
      COMPREPLY=($(compgen -f -- "$2")) ;;
    folder)
      compopt -o filenames 2>/dev/null
      COMPREPLY=($(compgen -d -- "$2")) ;;
    key)
      compopt -o nospace 2>/dev/null
      IFS=$' \t\n'
      COMPREPLY=($(compgen -W "$_systole_scene_keys" -S = -- "$2")) ;;
  esac
}

_systole() {
  COMPREPLY=()
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]} glued=0
  # bash splits --option=value at '=' (COMP_WORDBREAKS): put the option back in prev.
  if [[ $cur == = ]]; then
    cur="" glued=1
  elif [[ $prev == = ]]; then
    prev=${COMP_WORDS[COMP_CWORD-2]} glued=1
  fi
  # After key=, -D's value: nothing to offer.
  [[ $glued == 1 && $prev != -* ]] && return
  local command="" i
  for ((i = 1; i < COMP_CWORD; i++)); do
    if [[ ${COMP_WORDS[i]} != -* ]]; then
      command=${COMP_WORDS[i]}
      break
    fi
  done
  case $command in
    "")
)";
  std::vector<std::string> first_words;
  for (const auto& c : app.commands) first_words.push_back(c.name);
  for (const auto& n : all_names(app.options)) first_words.push_back(n);
  out << "      COMPREPLY=($(compgen -W '" << word_list(first_words) << "' -- \"$cur\"))\n      ;;\n";
  for (const auto& c : app.commands) write_bash_command(out, c);
  out << "  esac\n}\n\ncomplete -F _systole systole\n";
  return out.str();
}

std::string zsh_completion(const AppReference& app, const std::vector<std::string>& scene_keys) {
  std::ostringstream out;
  out << "#compdef systole\n"
      << "# zsh completion for systole. Generated by systole-manual from the command line's own definitions\n"
      << "# (src/cli/); do not edit.\n\n"
      << "_systole_scene_keys() {\n"
      << "  local -a keys\n"
      << "  keys=(" << word_list(completable_keys(scene_keys)) << ")\n"
      << "  compadd -S = -- $keys\n}\n\n"
      << "_systole() {\n"
      << "  local curcontext=$curcontext state line ret=1\n"
      << "  local -a commands\n"
      << "  commands=(\n";
  for (const auto& c : app.commands) out << "    '" << shell_word(c.name) << ":" << menu_text(c.description) << "'\n";
  out << "  )\n  _arguments -C";
  for (const auto& o : app.options) {
    std::string names;
    for (const auto& n : o.names) names += (names.empty() ? "" : ",") + shell_word(n);
    out << " \\\n    '(- *)'" << (o.names.size() > 1 ? "{" + names + "}" : names) << "'[" << menu_text(o.description) << "]'";
  }
  out << " \\\n    '1: :->command' \\\n    '*:: :->args' && ret=0\n"
      << "  case $state in\n"
      << "    command) _describe -t commands 'systole command' commands && ret=0 ;;\n"
      << "    args)\n      case $line[1] in\n";
  for (const auto& c : app.commands) write_zsh_command(out, c);
  out << "      esac\n      ;;\n  esac\n  return ret\n}\n\n_systole \"$@\"\n";
  return out.str();
}

}  // namespace systole::cli::manual
