#pragma once
// How `mms --help` and every subcommand's help read: wrapped to the terminal, defaults as
// "(default X)" after the description, and types a person reads ("INT in [1, 2000]", not
// CLI11's "INT:INT in [1 - 2000]=1").
#include <CLI/CLI.hpp>
#include <string>

namespace mms::cli {

/// The width help is wrapped to: the terminal's when standard output is one, else $COLUMNS,
/// else 100; between 60 and 120.
size_t helpWidth();

/// `text` wrapped to `width` columns, every line indented by `indent` spaces. Each line of
/// `text` stays a line of its own; its leading spaces are kept, and where it has some (an item
/// of a list) the lines it wraps into are indented two spaces more.
std::string wrapText(const std::string& text, size_t width, size_t indent);

class HelpFormatter final : public CLI::Formatter {
 public:
  explicit HelpFormatter(size_t width) : width_(width) {}
  /// A group under its title. CLI11 puts a blank line between groups and another before each
  /// title: only the first two (positionals, then "Options") keep their own.
  std::string make_group(std::string group, bool isPositional,
                         std::vector<const CLI::Option*> opts) const override;
  std::string make_option(const CLI::Option* opt, bool isPositional) const override;
  std::string make_option_opts(const CLI::Option* opt) const override;
  std::string make_option_desc(const CLI::Option* opt) const override;
  std::string make_description(const CLI::App* app) const override;
  /// A subcommand in the list of `mms --help`: its first sentence.
  std::string make_subcommand(const CLI::App* sub) const override;

 private:
  /// `left` in the first column and `text` wrapped beside it, or below it where `left` is
  /// wider than the column.
  std::string twoColumns(const std::string& left, const std::string& text) const;
  size_t width_;
};

/// The type CLI11 names for an option, as a person reads it: the validator's part where it
/// says more than the type ("INT:INT in [1 - 2000]" -> "INT in [1, 2000]"), choices as
/// "a|b|c" (or NAME where they are many: the description lists them).
std::string readableType(const std::string& cli11Type);

}  // namespace mms::cli
