#include "help_formatter.h"

#include <sstream>
#include <string>

namespace curvescan::cli {

PlainHelpFormatter::PlainHelpFormatter() {
  // Wide enough for "-b, --background-color, --background COLOUR" to stay beside most descriptions.
  column_width(34);
}

std::string PlainHelpFormatter::make_option_name(const CLI::Option* option, bool is_positional) const {
  if (is_positional) return option->get_name(/*positional=*/true, /*all_options=*/false);
  // "-z, --zoom": every spelling, without the "{false}" CLI11 appends to a negating flag's name.
  std::string names;
  const auto append = [&names](const std::string& name) { names += (names.empty() ? "" : ", ") + name; };
  for (const std::string& name : option->get_snames()) append("-" + name);
  for (const std::string& name : option->get_lnames()) append("--" + name);
  return names;
}

std::string PlainHelpFormatter::make_option_opts(const CLI::Option* option) const {
  const bool many = option->get_expected_max() >= CLI::detail::expected_max_vector_size;
  if (option->get_positional()) return many ? "..." : "";
  if (option->get_type_size() == 0) return {};  // a flag
  const std::string value =
      option->get_option_text().empty() ? option->get_type_name() : option->get_option_text();
  return " " + value + (many ? " ..." : "");
}

std::string PlainHelpFormatter::make_option_desc(const CLI::Option* option) const {
  std::string description = option->get_description();
  if (option->get_type_size() != 0 && !option->get_default_str().empty()) {
    description += " (default " + option->get_default_str() + ")";
  }
  if (option->get_required()) description += " (required)";
  return description;
}

std::string PlainHelpFormatter::make_subcommand(const CLI::App* subcommand) const {
  const std::string& description = subcommand->get_description();
  std::stringstream out;
  CLI::detail::format_help(out, subcommand->get_display_name(true),
                           description.substr(0, description.find('\n')), get_column_width());
  return out.str();
}

}  // namespace curvescan::cli
