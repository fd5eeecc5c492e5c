// mms: motion planning via manifold samples. Exit codes: 0 success, 1 negative answer (path
// rejected, no path), 2 bad input or usage, 3 internal error.
#include <CLI/CLI.hpp>
#include <iostream>

#include "Cli.h"
#include "Commands.h"
#include "HelpFormat.h"
#include "mms/mms.h"
#include "util/CommandBoundary.h"

int main(int argc, char** argv) {
  mms::cli::processClock();  // started: the time limits count from here
  using namespace mms::cli;
  CLI::App app{
      "mms: motion planning via manifold samples for planar polygonal robots.\n"
      "Scene and path formats: docs/formats.md. Exit codes: 0 success, 1 negative answer,\n"
      "2 bad input, 3 internal error."};
  // Before the subcommands, which take the app's formatter when they are added. Named, so that
  // usage lines read "mms plan ...", not the path the program was started by.
  app.name("mms");
  app.formatter(std::make_shared<HelpFormatter>(helpWidth()));
  app.set_version_flag("--version", std::string("mms ") + mms::version());
  app.require_subcommand(1);
  const std::vector<std::string> args(argv + 1, argv + argc);
  const std::vector<Command> commands = {addValidate(app),
                                         addCheck(app),
                                         addRender(app),
                                         addPlan(app),
                                         addScenario(app),
                                         addAssemble(app),
                                         addBench(app, std::vector<std::string>(argv, argv + argc)),
                                         addMerge(app),
                                         addView(app),
                                         addImport(app),
                                         addExport(app),
                                         addLab(app)};
  refuseNonFiniteNumbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // The help of the subcommand given, where one was: that is where its options are.
    const std::vector<CLI::App*> given = app.get_subcommands();
    const std::string help =
        given.empty() ? "mms --help" : "mms " + given[0]->get_name() + " --help";
    std::cerr << "mms: " << parseErrorLine(e, app, args) << " (see " << help << ")\n";
    return 2;
  }
  for (const Command& c : commands)
    if (*c.app) return mms::runAtBoundary(c.run, std::cerr);
  return 2;  // a subcommand is required, so this is not reached
}
