#include "cli/manual/reference.h"

#include "cli/command.h"

namespace systole::cli::manual {
namespace {

/// "TEXT:{auto,none,json}" -> value "TEXT", checks "{auto,none,json}" (CLI11 appends each
/// validator's description to the type name after a colon).
void split_type_name(const std::string& full, OptionReference& out) {
  const auto colon = full.find(':');
  out.value_name = full.substr(0, colon);
  out.checks = colon == std::string::npos ? "" : full.substr(colon + 1);
  if (out.checks.size() > 2 && out.checks.front() == '{' && out.checks.back() == '}') {
    const std::string list = out.checks.substr(1, out.checks.size() - 2);
    for (std::size_t start = 0; start <= list.size();) {
      const auto comma = std::min(list.find(',', start), list.size());
      out.choices.push_back(list.substr(start, comma - start));
      start = comma + 1;
    }
  }
}

ValueKind kind_of(const OptionReference& o) {
  if (o.flag()) return ValueKind::kNone;
  if (o.value_name == kSceneValue) return ValueKind::kScene;
  if (o.value_name == kFileValue) return ValueKind::kFile;
  if (o.value_name == kFolderValue) return ValueKind::kFolder;
  if (o.value_name == kSceneKeyValue) return ValueKind::kSceneKey;
  return ValueKind::kOther;
}

OptionReference describe_option(const CLI::Option& option) {
  OptionReference o;
  for (const auto& s : option.get_snames()) o.names.push_back("-" + s);
  for (const auto& l : option.get_lnames()) o.names.push_back("--" + l);
  if (o.names.empty()) o.positional_name = option.get_name(true);
  // A flag expects no value (type size 0); its type name would read "BOOLEAN" or be empty.
  if (option.get_type_size() != 0) split_type_name(option.get_type_name(), o);
  o.default_value = option.get_default_str();
  o.description = option.get_description();
  o.required = option.get_required();
  // A vector option takes many values and may be given again (-D a=1 -D b=2).
  o.repeatable = option.get_type_size() != 0 && option.get_items_expected_max() > 1;
  o.kind = kind_of(o);
  return o;
}

/// The options --help lists: those with a group (CLI11 hides an option by emptying its group).
std::vector<const CLI::Option*> visible_options(const CLI::App& app) {
  return app.get_options([](const CLI::Option* o) { return !o->get_group().empty(); });
}

}  // namespace

AppReference describe(const CLI::App& app, const std::string& version) {
  AppReference out;
  out.name = app.get_name();
  out.version = version;
  out.description = app.get_description();
  for (const CLI::Option* option : visible_options(app)) out.options.push_back(describe_option(*option));
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); })) {
    CommandReference command;
    command.name = sub->get_name();
    command.description = sub->get_description();
    for (const CLI::Option* option : visible_options(*sub)) {
      OptionReference o = describe_option(*option);
      (o.positional() ? command.positionals : command.options).push_back(std::move(o));
    }
    out.commands.push_back(std::move(command));
  }
  return out;
}

}  // namespace systole::cli::manual
