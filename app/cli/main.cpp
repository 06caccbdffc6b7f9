// sylva-cli: the headless front end of the Sylva engine (batch and farm use).
#include "cliargs.h"
#include "commands.h"
#include "terminalprogress.h"
#include "usage.h"

#include "document/errormessage.h"
#include "engine/util/error.h"
#include "engine/util/memorypolicy.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

const char* kUsage =
    "usage: sylva-cli <command> [options]\n"
    "\n"
    "commands:\n"
    "  expand <grammar> [-n N] [--seed S]      print the derived L-system string\n"
    "  tree <grammar|species.json> -o out.{formats}  generate one tree\n"
    "       [-n N] [--seed S] [--set node.param=value]... [--stats] [--fsync] [--compact]\n"
    "       [--wind [wind options]]\n"
    "  forest <project.sylva> -o out.{formats}  generate a forest\n"
    "       [--camera x,y,z] [--threads N] [--tile i/N] [--stats] [--no-lod]\n"
    "       [--no-adapt] [--no-neighbours] [--no-instancing] [--grow-unique]\n"
    "       [--instance-tables] [--naive-placement] [--fsync] [--full-precision] [--assimp-gltf]\n"
    "       [--wind [wind options]]\n"
    "  compose <root.usda> <tile.usda>...               root layer over a farm run's tiles\n"
    "  stats <project.sylva|species.json> [--json]       height, DBH, biomass, CO2\n"
    "  lods <species.json> -o <folder> [--json]          LOD chain for game engines\n"
    "  nodes [type] [--markdown|--json]         node types and their parameters\n"
    "  help [command]                          show this text, or one command's help\n"
    "\n"
    "'sylva-cli <command> --help' (or -h) shows a command's arguments and options.\n"
    "\n"
    "OBJ output: --fsync waits until the file is on disk before renaming it into place (atomic\n"
    "either way). Compact OBJ (0.1 mm positions, relative face indices, ~17 % smaller) is the\n"
    "default of forest (--full-precision: micrometres, absolute indices) and --compact of tree.\n"
    "\n"
    "exit status: 0 success, 1 bad input (message as file:line:col: error: ...), 2 bad usage,\n"
    "130 interrupted (Ctrl-C or SIGTERM; nothing written)\n";

void printError(const std::string& message) {
    // Engine messages with positions are already "file:line:col: error: ..."; others get the
    // program name so every line on stderr says where it came from.
    if (message.find(": error: ") != std::string::npos)
        std::fprintf(stderr, "%s\n", message.c_str());
    else
        std::fprintf(stderr, "sylva-cli: error: %s\n", message.c_str());
}

} // namespace

int run(int argc, char** argv) {
    using namespace sylva::cli;
    if (argc < 2) {
        std::fputs(expandFormats(kUsage).c_str(), stderr);
        return kBadUsage;
    }
    sylva::keepFreedMemory();
    const std::string command = argv[1];
    const std::vector<std::string> args(argv + 2, argv + argc);
    try {
        if (command == "help" || command == "--help" || command == "-h") {
            if (args.size() == 1) {
                // `help --help` asks for help's own usage, like every other command.
                const std::string& name =
                    args[0] == "--help" || args[0] == "-h" ? std::string("help") : args[0];
                const char* help = commandHelp(name);
                if (!help) throw UsageError("unknown command '" + name + "'");
                std::fputs(help, stdout);
                return kOk;
            }
            if (!args.empty()) throw UsageError(command + " takes at most one command name");
            std::fputs(expandFormats(kUsage).c_str(), stdout);
            return kOk;
        }
        if (command == "expand") return runExpand(args);
        if (command == "tree") return runTree(args);
        if (command == "forest") return runForest(args);
        if (command == "compose") return runCompose(args);
        if (command == "stats") return runStats(args);
        if (command == "lods") return runLods(args);
        if (command == "nodes") return runNodes(args);
        throw UsageError("unknown command '" + command + "'");
    } catch (const HelpRequested&) {
        std::fputs(commandHelp(command), stdout);
        return kOk;
    } catch (const sylva::Cancelled&) {
        std::fprintf(stderr, "sylva-cli: interrupted; no output written\n");
        return kInterrupted;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "sylva-cli: %s\n(see 'sylva-cli help')\n", e.what());
        return kBadUsage;
    } catch (...) {
        // The one mapping of exceptions to messages that the editor and Python share.
        const sylva::doc::ErrorReport report = sylva::doc::describeError(std::current_exception());
        printError(report.message);
        return kBadInput;
    }
}

/// OpenMP's threads wait for work by spinning (libgomp's default) unless OMP_WAIT_POLICY says
/// otherwise. On a shared machine (a farm node, a workstation that also runs the DCC) the
/// spinning takes CPU from the work: the 10,000-tree USD export took 7.5 s of CPU spinning and
/// 5.6 s passive, at load 12 (docs/perf/forest.md). libgomp reads the variable when it is
/// loaded, before main(): so the CLI sets PASSIVE and starts itself again, once, unless the
/// caller chose a policy.
static void preferPassiveWaiting(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") || std::getenv("SYLVA_NO_REEXEC")) return;
    ::setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
    ::setenv("SYLVA_NO_REEXEC", "1", 1); // never twice, whatever happens below
    ::execv("/proc/self/exe", argv);     // returns only when it failed: go on spinning
}

int main(int argc, char** argv) {
    preferPassiveWaiting(argv);
    const int status = run(argc, argv);
    if (status == sylva::cli::kInterrupted) {
        // An interrupted glTF/FBX export may leave Assimp's exporter running on a thread of its
        // own (it cannot be stopped; sceneexport.h): end without running static destructors
        // under it. Every temporary was removed while the command unwound.
        std::fflush(stdout);
        std::fflush(stderr);
        std::_Exit(status);
    }
    return status;
}
