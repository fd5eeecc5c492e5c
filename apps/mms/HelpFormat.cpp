#include "HelpFormat.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "bench/Runner.h"

namespace mms::cli {

size_t helpWidth() {
  size_t width = 100;
  winsize w{};
  if (isatty(STDOUT_FILENO) && ioctl(STDOUT_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0)
    width = w.ws_col;
  else if (const char* columns = std::getenv("COLUMNS"))
    width = size_t(std::max(0L, std::strtol(columns, nullptr, 10)));
  return std::clamp<size_t>(width, 60, 120);
}

namespace {

// A word wider than a line (a list of names without spaces) as pieces that end after a comma
// or a bar, each at most `room` wide where it can be.
void splitLongWord(std::string word, size_t room, std::vector<std::string>& out) {
  while (room >= 8 && word.size() > room) {
    const size_t cut = word.find_last_of(",|", room - 1);
    if (cut == std::string::npos) break;
    out.push_back(word.substr(0, cut + 1));
    word.erase(0, cut + 1);
  }
  out.push_back(word);
}

}  // namespace

std::string wrapText(const std::string& text, size_t width, size_t indent) {
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const size_t lead = std::min(line.find_first_not_of(' '), line.size());
    std::string current(indent + lead, ' ');
    bool empty = true;
    std::istringstream in(line.substr(lead));
    std::vector<std::string> words;
    for (std::string word; in >> word;) splitLongWord(word, width - indent - lead - 2, words);
    for (const std::string& word : words) {
      if (!empty && current.size() + 1 + word.size() > width) {
        out += current + '\n';
        current.assign(indent + lead + (lead > 0 ? 2 : 0), ' ');
        empty = true;
      }
      current += (empty ? "" : " ") + word;
      empty = false;
    }
    out += current + '\n';
  }
  return out;
}

std::string readableType(const std::string& cli11Type) {
  const std::vector<std::string> parts = split(cli11Type, ':');
  if (parts.empty()) return cli11Type;
  std::string type = parts[0];
  for (size_t i = 1; i < parts.size(); ++i) {
    const std::string& v = parts[i];
    if (v.size() >= 2 && v.front() == '{' && v.back() == '}') {
      std::string choices = v.substr(1, v.size() - 2);
      std::replace(choices.begin(), choices.end(), ',', '|');
      type = choices.size() <= 40 ? choices : "NAME";
    } else if (const size_t in = v.find(" in ["); in != std::string::npos) {
      type = v;
      if (const size_t dash = type.find(" - ", in); dash != std::string::npos)
        type.replace(dash, 3, ", ");
    }
  }
  return type;
}

std::string HelpFormatter::twoColumns(const std::string& left, const std::string& text) const {
  const size_t column = get_column_width();
  const std::string name = "  " + left;
  std::string body = wrapText(text.empty() ? " " : text, width_, column);
  if (name.size() + 1 <= column) return name + body.substr(name.size());
  return name + '\n' + body;
}

std::string HelpFormatter::make_group(std::string group, bool isPositional,
                                      std::vector<const CLI::Option*> opts) const {
  std::string out = isPositional || group == "Options" ? "\n" : "";
  out += group + ":\n";
  for (const CLI::Option* opt : opts) out += make_option(opt, isPositional);
  return out;
}

std::string HelpFormatter::make_option(const CLI::Option* opt, bool isPositional) const {
  return twoColumns(make_option_name(opt, isPositional) + make_option_opts(opt),
                    make_option_desc(opt));
}

std::string HelpFormatter::make_option_opts(const CLI::Option* opt) const {
  if (!opt->get_option_text().empty()) return " " + opt->get_option_text();
  if (opt->get_type_size() == 0) return "";  // a flag
  const std::string type = readableType(opt->get_type_name());
  std::string out = type == opt->get_name() ? "" : " " + type;  // NAME NAME: once is enough
  if (opt->get_expected_max() == CLI::detail::expected_max_vector_size) out += " ...";
  if (opt->get_required()) out += " (required)";
  return out;
}

std::string HelpFormatter::make_option_desc(const CLI::Option* opt) const {
  std::string desc = opt->get_description();
  const std::string shown = opt->get_default_str();
  if (!shown.empty() && opt->get_type_size() != 0 && desc.find("(default") == std::string::npos)
    desc += " (default " + shown + ")";
  return desc;
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
  const std::string desc = app->get_description();
  return desc.empty() ? "" : wrapText(desc, width_, 0) + '\n';
}

std::string HelpFormatter::make_subcommand(const CLI::App* sub) const {
  std::string text = sub->get_description();
  std::replace(text.begin(), text.end(), '\n', ' ');
  if (const size_t end = text.find(". "); end != std::string::npos) text.erase(end + 1);
  return twoColumns(sub->get_display_name(true), text);
}

}  // namespace mms::cli
