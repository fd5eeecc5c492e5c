#pragma once
// The command line's subcommands, one registration function each (apps/mms/Cli.cpp).
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace mms::cli {

/// A subcommand: registered on the app, and what runs when it is the one given.
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

Command addValidate(CLI::App& app);
Command addCheck(CLI::App& app);
Command addRender(CLI::App& app);
Command addPlan(CLI::App& app);
Command addScenario(CLI::App& app);
Command addAssemble(CLI::App& app);
/// `argv`: the command line, logged with the results so that it can run again.
Command addBench(CLI::App& app, const std::vector<std::string>& argv);
Command addMerge(CLI::App& app);
Command addView(CLI::App& app);
Command addImport(CLI::App& app);
Command addExport(CLI::App& app);
Command addLab(CLI::App& app);

/// Every option of every subcommand that CLI11 reads as a floating-point number refuses NaN
/// and infinity (those registered with a range already do, the others through this).
void refuseNonFiniteNumbers(CLI::App& app);

/// A CLI11 parse error as one line in the words of mms's other messages, with the name likely
/// meant where a name was mistyped; `args` are the command line's arguments after the program.
std::string parseErrorLine(const CLI::ParseError& e, const CLI::App& app,
                           const std::vector<std::string>& args);

}  // namespace mms::cli
