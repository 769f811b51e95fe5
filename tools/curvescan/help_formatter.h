// The help every subcommand prints (`curvescan <command> --help`): options in plain words. CLI11's own
// formatter shows the parser's view of an option ("FLOAT:FINITE:FLOAT in [1e-09 - 1e+09]=0.1",
// "Excludes: --quiet", "--no-keep-image-data{false}"); this one shows what a user types and what it means:
//
//   -z, --zoom FACTOR           scale factor for both axes, 1e-9 to 1e9 (default 1)
//
// - the value is named by the option's type_name ("FACTOR", "LENGTH", "MiB", "FILE"), or its option_text
//   when set; validators have empty descriptions (option_range.h), so CLI11 appends nothing to the name
//   and its own messages use the same word ("--zoom: 1 required FACTOR missing");
// - the range, the unit and any "not with --x" are said in the description, in words;
// - a default captured with capture_default_str() is appended as "(default X)", and a required option
//   says "(required)";
// - `curvescan --help` lists each subcommand with the first line of its description (the examples are in
//   the subcommand's own help).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace curvescan::cli {

class PlainHelpFormatter : public CLI::Formatter {
 public:
  PlainHelpFormatter();
  std::string make_option_name(const CLI::Option* option, bool is_positional) const override;
  std::string make_option_opts(const CLI::Option* option) const override;
  std::string make_option_desc(const CLI::Option* option) const override;
  std::string make_subcommand(const CLI::App* subcommand) const override;
};

}  // namespace curvescan::cli
