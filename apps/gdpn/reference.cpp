// `gdpn reference`: the command-line reference, written from the program's own option
// definitions (docs/cli.md as Markdown, the man page gdpn.1 as roff), so that neither can drift
// from what the program accepts.

#include <iostream>
#include <string>
#include <vector>

#include "commands.h"

namespace gdpn::app {

namespace {

/// The subcommands a user sees (a hidden one has no group).
std::vector<const CLI::App*> visibleSubcommands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); });
}

/// The options a user sees, the help flag left out (every command has it).
std::vector<const CLI::Option*> visibleOptions(const CLI::App& cmd) {
  return cmd.get_options([](const CLI::Option* o) { return !o->get_group().empty() && o->get_name() != "--help"; });
}

/// How an option is written: its names, then what it takes (`--at FLOAT x 3`, `MODEL`).
std::string optionSyntax(const CLI::Option& o) {
  std::string names = o.get_positional() ? o.get_name(true) : o.get_name(false, true);
  // a flag's names carry its value when given ("--no-shadows{false}"): the names alone
  if (auto brace = names.find('{'); brace != std::string::npos) names.resize(brace);
  std::string type = o.get_type_name();
  // the type names of validated options carry the check ("FLOAT:seconds above 0"): the type alone
  if (auto colon = type.find(':'); colon != std::string::npos) type.resize(colon);
  if (o.get_positional() || o.get_expected_max() == 0 || type.empty()) return names;
  if (o.get_expected_max() > 1 && o.get_expected_max() < CLI::detail::expected_max_vector_size)
    type += " x " + std::to_string(o.get_expected_max());
  else if (o.get_items_expected_max() >= CLI::detail::expected_max_vector_size)
    type += " ...";
  return names + " " + type;
}

/// The usage line of `cmd` under the program `program`: its name, [OPTIONS] and its positionals.
std::string usage(const std::string& program, const CLI::App& cmd) {
  std::string out = program + " " + cmd.get_name();
  if (!visibleOptions(cmd).empty()) out += " [OPTIONS]";
  for (const auto* o : cmd.get_options([](const CLI::Option* x) { return x->get_positional(); })) {
    const std::string name = o->get_name(true);
    out += " " + (o->get_required() ? name : "[" + name + "]");
  }
  return out;
}

/// An option's default as the reference shows it: CLI11's default text, "off" for a flag.
std::string defaultText(const CLI::Option& o) {
  if (!o.get_default_str().empty() && o.get_expected_max() > 0) return o.get_default_str();
  return o.get_expected_max() == 0 && !o.get_positional() ? "off" : "";
}

/// A table cell: no line breaks, no pipes.
std::string cell(std::string text) {
  for (auto& c : text)
    if (c == '\n') c = ' ';
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

void markdown(const CLI::App& app, std::ostream& os) {
  os << "# gdpn: the command-line reference\n\n"
     << "Written by `gdpn reference --format markdown` from the program's own option definitions;\n"
     << "the test `docs.references` fails when this file differs from what the program says\n"
     << "(`gdpn reference --format markdown > docs/cli.md` brings it up to date). Every command also\n"
     << "answers `gdpn COMMAND --help`. The same text is the man page, `man gdpn`.\n\n"
     << app.get_description() << "\n\n";
  for (const auto* cmd : visibleSubcommands(app)) os << "- [`gdpn " << cmd->get_name() << "`](#gdpn-" << cmd->get_name()
                                                     << "): " << cmd->get_description() << "\n";
  os << "\nEvery command exits 0 when it did what was asked and 2 when its arguments are wrong (after\n"
     << "saying which); other codes are the command's own, given below.\n";
  for (const auto* cmd : visibleSubcommands(app)) {
    os << "\n## gdpn " << cmd->get_name() << "\n\n" << cmd->get_description() << ".\n\n";
    os << "```\n" << usage("gdpn", *cmd) << "\n```\n\n";
    os << "| argument or option | what it is | default |\n| --- | --- | --- |\n";
    for (const auto* o : visibleOptions(*cmd)) {
      os << "| `" << cell(optionSyntax(*o)) << "` | " << cell(o->get_description())
         << (o->get_required() && !o->get_positional() ? " (required)" : "") << " | "
         << (defaultText(*o).empty() ? "" : "`" + cell(defaultText(*o)) + "`") << " |\n";
    }
    if (const std::string footer = cmd->get_footer(); !footer.empty()) os << "\n```\n" << footer << "\n```\n";
  }
}

/// Text for roff: backslashes and hyphens escaped, no line starting with a control character.
std::string roff(const std::string& text) {
  std::string out;
  bool line_start = true;
  for (char c : text) {
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
    line_start = c == '\n';
  }
  return out;
}

void man(const CLI::App& app, std::ostream& os) {
  os << ".\\\" Written by `gdpn reference --format man` from the program's own option definitions.\n"
     << ".TH GDPN 1 \"\" \"gdpn " << GDPN_VERSION << "\" \"User Commands\"\n"
     << ".SH NAME\ngdpn \\- geometry\\-driven Petri nets: model, run and analyse control logic against a "
        "virtual plant\n"
     << ".SH SYNOPSIS\n.B gdpn\n.I COMMAND\n[\\fIOPTIONS\\fR] [\\fIARGUMENTS\\fR]\n.br\n.B gdpn\n\\-\\-version\n"
     << ".SH DESCRIPTION\n"
     << roff(app.get_description()) << "\nEvery command exits 0 when it did what was asked and 2 when its "
     << "arguments are wrong; other codes are the command's own.\n.SH COMMANDS\n";
  for (const auto* cmd : visibleSubcommands(app)) {
    os << ".SS \"" << roff(usage("gdpn", *cmd)) << "\"\n" << roff(cmd->get_description()) << ".\n";
    for (const auto* o : visibleOptions(*cmd)) {
      os << ".TP\n.B " << roff(optionSyntax(*o)) << "\n" << roff(o->get_description());
      if (!defaultText(*o).empty()) os << " (default: " << roff(defaultText(*o)) << ")";
      os << "\n";
    }
    if (const std::string footer = cmd->get_footer(); !footer.empty())
      os << ".PP\n.nf\n" << roff(footer) << "\n.fi\n";
  }
  os << ".SH FILES\n.TP\n.I /usr/share/gdpn/parts\nthe parts library (also $XDG_DATA_HOME/gdpn/parts)\n"
     << ".TP\n.I /usr/share/gdpn/examples\nthe examples\n"
     << ".TP\n.I /usr/share/doc/gdpn\nthe guides: format, semantics, queries, parts, the IDE\n"
     << ".SH SEE ALSO\n.BR python3 (1):\n.B import gdpn\n(the same library from Python)\n";
}

}  // namespace

Subcommand addReference(CLI::App& app) {
  auto format = std::make_shared<std::string>("markdown");
  auto* cmd = app.add_subcommand("reference", "Write this program's command-line reference (docs/cli.md, the man page)");
  cmd->group("");  // for the build and the docs, not for users
  cmd->add_option("--format", *format, "markdown or man")->check(CLI::IsMember({"markdown", "man"}));
  return {cmd, [&app, format] {
            if (*format == "man")
              man(app, std::cout);
            else
              markdown(app, std::cout);
            return std::cout.good() ? 0 : 1;
          }};
}

}  // namespace gdpn::app
