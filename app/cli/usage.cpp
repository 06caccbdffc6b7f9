#include "usage.h"

#include <cstring>

namespace sylva::cli {

namespace {

struct CommandHelp {
    const char* name;
    const char* text;
};

// Kept in step with docs/cli.md; tests/cli/cli_tests.sh checks every command prints its own.
constexpr CommandHelp kHelp[] = {
    {"expand",
     "usage: sylva-cli expand <grammar> [-n GENERATIONS] [--seed S] [--limit SYMBOLS]\n"
     "                        [--time-limit SECONDS]\n"
     "\n"
     "Prints the derived L-system word on one line.\n"
     "\n"
     "options:\n"
     "  -n, --generations N   rewriting steps, 0..1000 (default: the grammar's generations:)\n"
     "  --seed S              seed of stochastic rules and rand() (default: the grammar's seed:)\n"
     "  --limit SYMBOLS       most modules a generation may hold, 1..2000000000\n"
     "                        (default 20000000; past it the command fails with exit status 1)\n"
     "  --time-limit SECONDS  most seconds the derivation may take, 1..86400 (default 300;\n"
     "                        past it the command fails with exit status 1)\n"
     "  -h, --help            show this text\n"},
    {"tree",
     "usage: sylva-cli tree <grammar.lsys|species.json> -o out.{obj,glb,gltf,fbx} [options]\n"
     "\n"
     "Generates one tree and writes it in the format of the output's extension.\n"
     "\n"
     "options:\n"
     "  -o, --output FILE     the file to write (.obj with .mtl and textures, .glb, .gltf, .fbx)\n"
     "  -n, --generations N   sets generations (0..1000) on every lsystem node\n"
     "  --seed S              seed of every generator\n"
     "  --set node.param=V    changes one node parameter (V is JSON or a string); repeatable\n"
     "  --season NAME         spring, summer, autumn or winter (the tube_mesh's season)\n"
     "  --stats               prints symbols, segments, vertices, triangles, height, timings\n"
     "                        as one JSON object on stdout\n"
     "  --compact             compact OBJ (0.1 mm positions, relative face indices)\n"
     "  --fsync               waits until the OBJ is on disk before renaming it into place\n"
     "  -h, --help            show this text\n"},
    {"forest",
     "usage: sylva-cli forest <project.sylva|scene.json> -o out.{obj,glb,gltf,fbx} [options]\n"
     "\n"
     "Builds the whole forest of a project (placement, adaptation to obstacles and neighbours,\n"
     "LOD meshing, metrics) and writes it as one file, one object per tree.\n"
     "\n"
     "options:\n"
     "  -o, --output FILE     the file to write (.obj, .glb, .gltf, .fbx)\n"
     "  --camera x,y,z        camera position for LOD (metres; default: the project's camera)\n"
     "  --threads N           threads, 1..1024 (the output is the same for any N)\n"
     "  --tile i/N            only tile i of N deterministic spatial tiles (farm runs)\n"
     "  --season NAME         every tree in spring, summer, autumn or winter (default: the\n"
     "                        project's and each tree's own season)\n"
     "  --stats               prints counts, metrics and timings as one JSON object on stdout\n"
     "  --no-lod              meshes every tree at full detail\n"
     "  --no-adapt            skips adaptation to obstacles and neighbours\n"
     "  --no-neighbours       ignores neighbouring crowns when adapting\n"
     "  --instance-tables     also writes <name>.instances.json and .csv\n"
     "  --naive-placement     the O(n^2) placement oracle instead of the grid (same result)\n"
     "  --full-precision      micrometre OBJ with absolute indices (default: compact)\n"
     "  --fsync               waits until the OBJ is on disk before renaming it into place\n"
     "  -h, --help            show this text\n"},
    {"stats",
     "usage: sylva-cli stats <project.sylva|species.json|grammar> [--json] [--seed S]\n"
     "\n"
     "Height, DBH at 1.3 m, crown width, wood volume, dry biomass, carbon and CO2 equivalent\n"
     "of one tree of a species, or summed over a project's trees.\n"
     "\n"
     "options:\n"
     "  --json                one JSON object (with per_tree for a project) instead of a table\n"
     "  --seed S              seed of the species' generator (species and grammars)\n"
     "  -h, --help            show this text\n"},
    {"lods",
     "usage: sylva-cli lods <species.json|grammar> -o <folder> [--seed S] [--json] [--no-glb]\n"
     "                      [--no-obj]\n"
     "\n"
     "Writes a species' level-of-detail chain for game engines: <species>_LOD<i>.obj and\n"
     "<species>_LODs.glb, and prints each level's distance, triangles and vertices.\n"
     "\n"
     "options:\n"
     "  -o, --output FOLDER   the folder to write into (created when missing)\n"
     "  --seed S              seed of the species' generator\n"
     "  --json                the levels as one JSON object instead of a table\n"
     "  --no-glb, --no-obj    skip the glTF file or the OBJ files\n"
     "  -h, --help            show this text\n"},
    {"nodes",
     "usage: sylva-cli nodes [type] [--markdown | --json]\n"
     "\n"
     "Lists the species graph's node types: what each takes and makes, and every parameter with\n"
     "its type, default, range, unit and meaning (the paper's symbol where there is one). The\n"
     "same table validates species files and builds the editor's parameter panels.\n"
     "\n"
     "options:\n"
     "  --markdown            the tables of docs/species.md\n"
     "  --json                one JSON array (for scripts and other tools)\n"
     "  -h, --help            show this text\n"},
    {"help",
     "usage: sylva-cli help [command]\n"
     "\n"
     "Lists the commands, or shows one command's help (the same as sylva-cli <command> --help).\n"
     "\n"
     "options:\n"
     "  -h, --help            show this text\n"},
};

} // namespace

const char* commandHelp(const std::string& command) {
    for (const CommandHelp& h : kHelp)
        if (command == h.name) return h.text;
    return nullptr;
}

std::string commandUsageLine(const std::string& command) {
    const char* text = commandHelp(command);
    if (!text) return {};
    return std::string(text, std::strchr(text, '\n'));
}

} // namespace sylva::cli
