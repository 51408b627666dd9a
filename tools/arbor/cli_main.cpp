#include "cli_main.hpp"

#include <cstdio>
#include <cstring>
#include <malloc.h>

#include "common/input_error.hpp"

namespace arbor::cli {

namespace {

constexpr const char* kDescription = "Arbor: Weber-Penn trees as one connected quad mesh, refined by GPU tessellation.";

void configure(CLI::App& app) {
  app.set_version_flag("--version", std::string("arbor ") + ARBOR_VERSION);
  app.require_subcommand(1);
}

}  // namespace

int runGuarded(const Action& action) {
  try {
    return action();
  } catch (const InputError& e) {
    std::fprintf(stderr, "arbor: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const LimitError& e) {
    std::fprintf(stderr, "arbor: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arbor: error: %s\n", e.what());
    return kExitFailure;
  }
}

int runCli(int argc, char** argv, std::span<const AddCommand> commands, const std::function<int(const Action&)>& guard,
           const std::function<int()>& otherwise) {
  // Trees are rebuilt in place (viewer edits, benchmarks): keep freed blocks for reuse instead of handing
  // tens of megabytes back to the kernel and faulting them in again on the next tree.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  CLI::App app{kDescription, "arbor"};
  configure(app);
  Action action;
  for (AddCommand add : commands) add(app, action);
  if (otherwise && !(argc == 2 && std::strcmp(argv[1], "--version") == 0)) {
    bool named = false;
    for (const CLI::App* sub : app.get_subcommands({})) named = named || (argc > 1 && sub->get_name() == argv[1]);
    if (!named) return otherwise();
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 says "A subcommand is required" for a mistyped one too: name it and the commands there are.
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
      known = known || (argc > 1 && sub->get_name() == argv[1]);
    }
    if (argc > 1 && argv[1][0] != '-' && !known) {
      std::fprintf(stderr, "arbor: usage error: unknown command '%s'; commands: %s\nRun 'arbor --help'.\n", argv[1], names.c_str());
      return kExitBadInput;
    }
    std::fprintf(stderr, "arbor: usage error: %s\nRun 'arbor --help' or 'arbor <command> --help'.\n", e.what());
    return kExitBadInput;
  }
  return action ? guard(action) : kExitBadInput;
}

}  // namespace arbor::cli
