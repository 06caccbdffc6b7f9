#include "usage.h"

#include <cstring>
#include <deque>

#include "document/projectsettings.h"
#include "engine/export/formats.h"
#include "engine/util/text.h"

namespace sylva::cli {

namespace {

struct CommandHelp {
    const char* name;
    const char* text;
};

// Kept in step with docs/cli.md; "{wind.*}" stand for a setting's range and default from the
// project settings' spec (core/document/projectsettings.h); "{formats}" and "{extensions}" stand
// for the format table's extensions (expandFormats); tests/cli/cli_tests.sh checks every command
// prints its own.
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
     "usage: sylva-cli tree <grammar.lsys|species.json> -o out.{formats}\n"
     "                      [options]\n"
     "\n"
     "Generates one tree and writes it in the format of the output's extension.\n"
     "\n"
     "options:\n"
     "  -o, --output FILE     the file to write (.obj with .mtl and textures, .usda, .glb,\n"
     "                        .gltf, .fbx)\n"
     "  -n, --generations N   sets generations (0..1000) on every lsystem node\n"
     "  --seed S              seed of every generator\n"
     "  --set node.param=V    changes one node parameter (V is JSON or a string); repeatable\n"
     "  --season NAME         spring, summer, autumn or winter (the tube_mesh's season)\n"
     "  --stats               prints symbols, segments, vertices, triangles, height, timings\n"
     "                        as one JSON object on stdout\n"
     "  --compact             compact OBJ (0.1 mm positions, relative face indices)\n"
     "  --fsync               waits until the OBJ is on disk before renaming it into place\n"
     "  --wind                also writes the wind model (docs/wind.md): .glb/.gltf with _WIND*\n"
     "                        attributes, a low-bone skin and a looping clip; .fbx with bones and\n"
     "                        an animation stack; both with Unreal's Pivot Painter 2 textures\n"
     "                        (<name>_pivot_index.exr, <name>_xaxis_extent.png, UV 1); and\n"
     "                        <name>.wind.csv with the per-vertex channels\n"
     "  --bones N             bone budget per tree, 2..1024 (default 64)\n"
     "  --clip-length S       clip seconds, 0.5..600 (default 4); the motion repeats after it\n"
     "  --clip-fps N          clip frames per second, 1..240 (default 30)\n"
     "  --wind-direction x,y,z  where the wind blows to (default 1,0,0; only x and z count)\n"
     "  --wind-strength S     {wind.strength}   --wind-gustiness G  {wind.gustiness}\n"
     "  --wind-frequency F    the trunk's sway in Hz, {wind.frequency}\n"
     "  -h, --help            show this text\n"},
    {"forest",
     "usage: sylva-cli forest <project.sylva|scene.json> -o out.{formats}\n"
     "                        [options]\n"
     "\n"
     "Builds the whole forest of a project (placement, adaptation to obstacles and neighbours,\n"
     "LOD meshing, metrics) and writes it as one file, one object per tree.\n"
     "\n"
     "options:\n"
     "  -o, --output FILE     the file to write ({extensions}); .usda: a USD\n"
     "                        stage (PointInstancers, unique trees as meshes; docs/usd.md)\n"
     "  --camera x,y,z        camera position for LOD (metres; default: the project's camera)\n"
     "  --threads N           threads, 1..1024 (the output is the same for any N)\n"
     "  --tile i/N            only tile i of N deterministic spatial tiles (farm runs); with\n"
     "                        .usda a tile layer for 'sylva-cli compose'\n"
     "  --season NAME         every tree in spring, summer, autumn or winter (default: the\n"
     "                        project's and each tree's own season)\n"
     "  --stats               prints counts, metrics and timings as one JSON object on stdout\n"
     "  --no-lod              meshes every tree at full detail\n"
     "  --no-adapt            skips adaptation to obstacles and neighbours\n"
     "  --no-neighbours       ignores neighbouring crowns when adapting\n"
     "  --no-instancing       grows every tree for its place (default: free domain trees\n"
     "                        show one of their species' variants; OBJ writes them merged)\n"
     "  --grow-unique         grows each tree that touches an obstacle or a neighbour from\n"
     "                        its own seed (default: adapts its variant's skeleton instead)\n"
     "  --instance-tables     also writes <name>.instances.json and .csv\n"
     "  --naive-placement     the O(n^2) placement oracle instead of the grid (same result)\n"
     "  --full-precision      micrometre OBJ with absolute indices, shortest round-trip USD\n"
     "                        mesh numbers (default: compact, 0.1 mm)\n"
     "  --fsync               waits until the OBJ or USD is on disk before renaming it\n"
     "  --assimp-gltf         .glb/.gltf through Assimp's exporter (slow; for comparison)\n"
     "  --wind                every tree with the wind model (docs/wind.md), as tree --wind,\n"
     "                        in the project's \"wind\" (the default when the project has one:\n"
     "                        .glb, .gltf, .fbx, .obj); --bones, --clip-length, --clip-fps and\n"
     "                        --wind-* override its settings\n"
     "  --no-wind             no wind model, even when the project has a wind\n"
     "  -h, --help            show this text\n"
     "\n"
     "Ctrl-C or SIGTERM stops within a second, removes the temporary files and exits 130.\n"},
    {"compose",
     "usage: sylva-cli compose <root.usda> <tile.usda>...\n"
     "\n"
     "Writes the root layer of a farm run: the stage's metadata (Y up, metres, defaultPrim\n"
     "Forest) and subLayers naming the tiles (paths relative to the root), so that the\n"
     "composed stage is the single run's forest, tree for tree. Every tile of the run must be\n"
     "given once, all written by 'sylva-cli forest --tile i/N' from the same project and\n"
     "options (else exit status 1, naming what is missing or foreign). Reads only the tiles'\n"
     "headers.\n"
     "\n"
     "options:\n"
     "  -h, --help            show this text\n"},
    {"stats",
     "usage: sylva-cli stats <project.sylva|species.json|grammar> [--json] [--seed S]\n"
     "\n"
     "Height, DBH at 1.3 m, crown width, wood volume, dry biomass, carbon and CO2 equivalent\n"
     "of one tree of a species, or summed over a project's trees (with how many are instanced,\n"
     "unique, and the variants; --json lists every tree with its id and variant).\n"
     "\n"
     "options:\n"
     "  --json                one JSON object (with per_tree for a project) instead of a table\n"
     "  --seed S              seed of the species' generator (species and grammars)\n"
     "  -h, --help            show this text\n"},
    {"lods",
     "usage: sylva-cli lods <species.json|grammar> -o <folder> [--seed S] [--json]\n"
     "                      [--budgets 1,0.35,0.12,0.04] [--impostor-grid N]\n"
     "                      [--impostor-cell PX] [--impostor-pixels PX] [--octahedral]\n"
     "                      [--min-silhouette IOU]\n"
     "                      [--no-impostor] [--no-glb] [--no-fbx] [--no-usd] [--no-obj]\n"
     "\n"
     "Writes a species' LOD chain for game engines (docs/lods.md): LOD0..LODn by triangle\n"
     "budget and a baked octahedral impostor (<species>_impostor_color/normal/depth.png), as\n"
     "<species>_LODs.glb (MSFT_lod), <species>_LODs.fbx, <species>_lods.usda (a \"lod\"\n"
     "variant set), <species>_LOD<i>.obj and the\n"
     "description <species>_lods.json; prints each level's budget, switch distance, screen\n"
     "size and triangles.\n"
     "\n"
     "options:\n"
     "  -o, --output FOLDER   the folder to write into (created when missing)\n"
     "  --seed S              seed of the species' generator\n"
     "  --json                print the description (<species>_lods.json) instead of a table\n"
     "  --budgets LIST        triangles of each level as fractions of LOD0's (first 1,\n"
     "                        decreasing; default 1,0.35,0.12,0.04)\n"
     "  --impostor-grid N     N x N views in the atlas, 2..32 (default 8)\n"
     "  --impostor-cell PX    pixels of one view, 8..2048 (default 256)\n"
     "  --impostor-pixels PX  the impostor takes over where the tree spans PX pixels of a\n"
     "                        1080-pixel view (default 64)\n"
     "  --octahedral          views of the whole sphere instead of the upper hemisphere\n"
     "  --min-silhouette IOU  the silhouette IoU each level keeps against LOD0 at its switch\n"
     "                        distance, else it is remade with other leaf clusters; 0: no\n"
     "                        check (default 0.9)\n"
     "  --no-impostor         mesh levels only\n"
     "  --no-glb, --no-fbx, --no-usd, --no-obj   skip that file kind\n"
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

namespace {
/// "0..2 (default 0.5)": a setting's range and default from the project settings' spec.
std::string rangeOf(const doc::SettingSpec& spec) {
    return shortestDecimal(spec.min) + ".." + shortestDecimal(spec.max) + " (default " +
           shortestDecimal(spec.defaultValue) + ")";
}
} // namespace

std::string expandFormats(std::string text) {
    const std::pair<const char*, std::string> keys[] = {
        {"{formats}", exporter::extensionList(nullptr, ",", ",", false)},
        {"{extensions}", exporter::extensionList(nullptr, ", ", ", ")},
        {"{wind.strength}", rangeOf(doc::settings::kWindStrength)},
        {"{wind.gustiness}", rangeOf(doc::settings::kWindGustiness)},
        {"{wind.frequency}", rangeOf(doc::settings::kWindFrequency)}};
    for (const auto& key : keys)
        for (std::size_t at = text.find(key.first); at != std::string::npos;
             at = text.find(key.first, at))
            text.replace(at, std::strlen(key.first), key.second);
    return text;
}

const char* commandHelp(const std::string& command) {
    static std::deque<std::string> expanded(std::size(kHelp)); // made once, kept for the process
    for (std::size_t i = 0; i < std::size(kHelp); ++i)
        if (command == kHelp[i].name) {
            if (expanded[i].empty()) expanded[i] = expandFormats(kHelp[i].text);
            return expanded[i].c_str();
        }
    return nullptr;
}

std::string commandUsageLine(const std::string& command) {
    const char* text = commandHelp(command);
    if (!text) return {};
    return std::string(text, std::strchr(text, '\n'));
}

} // namespace sylva::cli
